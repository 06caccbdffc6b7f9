#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/mesh/season.h"

namespace sylva::mesh {

/// How much a species' leaf cards differ in colour in one season (issue #33: a real crown is
/// never one green; every card of ours had the same tint). Each card gets a colour around the
/// species' leaf colour: its hue turned by up to ±hue degrees, its saturation scaled by up to
/// ±saturation, its brightness lowered by up to brightness. All zero: no variation.
struct LeafColorVariation {
    double hue = 0.0;        ///< degrees, [0, 90]
    double saturation = 0.0; ///< fraction of the leaf colour's saturation, [0, 1]
    double brightness = 0.0; ///< fraction of its brightness the darkest card loses, [0, 1]
    bool active() const { return hue > 0.0 || saturation > 0.0 || brightness > 0.0; }
};

/// A species' leaf colour variation (tube_mesh's `leaf_hue_variation`,
/// `leaf_saturation_variation`, `leaf_brightness_variation`, their `leaf_autumn_*` twins,
/// `leaf_color_patch`, `autumn_color`).
struct LeafTintSettings {
    LeafColorVariation summer; ///< spring and summer, and an evergreen all year
    LeafColorVariation autumn; ///< a deciduous species in autumn
    /// Metres: most of a card's variation (60 %) follows a smooth noise of about this size over
    /// the crown (a branch's leaves alike, its neighbour's a little different), the rest is its
    /// own; 0: every card on its own. [0, 1000].
    double patchSize = 1.5;
    glm::vec3 autumnColor{0.6f, 0.4f, 0.1f}; ///< sRGB 0..1: the colour autumn's hue turns around
    /// Fraction of its brightness the most shaded card loses by the growth's own light
    /// (leafCardLight: outer, sun-facing cards lighter, inner darker), in every season; 0: the
    /// light records are not shown. [0, 1].
    double lightShading = 0.0;
};

/// The variation a season shows (autumn's for a deciduous species in autumn, else summer's).
const LeafColorVariation& leafVariationFor(const LeafTintSettings& settings, Season season,
                                           bool deciduous);

/// The colour (sRGB 0..1) a season's variation turns around: the summer green of Sylva's leaf
/// textures, a lighter green in spring, the species' autumn colour in autumn.
glm::vec3 leafReferenceColor(const LeafTintSettings& settings, Season season, bool deciduous);

/// The multiplier of a leaf colour \p referenceSrgb whose hue is turned by \p hue degrees
/// (HSV: negative toward yellow and red, positive toward cyan for a green), its saturation
/// scaled by 1 + \p saturation and its HSV value by \p value (≤ 1): the new colour divided by
/// the reference in linear light, each channel in [0.25, 1]. A multiplier cannot brighten a
/// texture: where a channel would have to grow, all are scaled down until it need not (the hue
/// turns, the card is darker). Alpha 255.
glm::u8vec4 tintMultiplier(const glm::vec3& referenceSrgb, double hue, double saturation,
                           double value);

/// tintMultiplier for many cards: \p hue, \p saturation and \p value of each card, its
/// multiplier in \p out (all four the same length). The same bytes as tintMultiplier card by
/// card; eight cards at a time, each stage of the computation for all eight before the next
/// (their chains of divisions and powf overlap: what tintLeafCards uses).
void tintMultipliers(const glm::vec3& referenceSrgb, std::span<const double> hue,
                     std::span<const double> saturation, std::span<const double> value,
                     std::span<glm::u8vec4> out);

/// The bounds the multipliers take, with AVX-512, on srgbToLinear's powf(a, 2.4f) instead of
/// calling it (where the bytes made from both bounds agree, they are the bytes powf would give):
/// for each float of \p a (each in [2^-4, 1]) in \p lo and \p hi. False, nothing written, where
/// the multipliers call powf (no AVX-512, SYLVA_NO_AVX512 or SYLVA_NO_AVX). For the tests: powf
/// must lie within them for every such a.
bool tintPowfBounds(std::span<const float> a, std::span<double> lo, std::span<double> hi);

/// The box of \p points (not empty) in \p lo and \p hi: glm::min and glm::max from the first
/// point on, four points a step on SSE2 as four chains side by side (one chain of every point,
/// each step waiting on the one before it, was most of the box's time). The same box as the
/// plain loop, NaN points skipped alike; where +0 and -0 are both an axis's extreme, either
/// may be the one kept (tintLeafCards' colours do not depend on the box: only which noise
/// lattice values are kept in ValueNoise's grid).
void vertexBox(std::span<const glm::vec3> points, glm::vec3& lo, glm::vec3& hi);

/// Gives the quads (four vertices a card, as appendLeafCards and appendLeafClusterCards make
/// them) from \p firstVertex to the end of \p mesh their Mesh::colors: each card one colour,
/// from a random of \p seed and the card's centre to a millimetre (the two sheets of a crossed
/// card share it; the same card, the same colour, whatever
/// the thread count or the order cards are made in) mixed 40 : 60 with a smooth noise over the
/// crown (LeafTintSettings::patchSize). Vertices before \p firstVertex get white when
/// the mesh had no colours. \p cardLight (one value a card in [0, 1], leafCardLight's) darkens
/// each card's HSV value by the factor 1 - \p lightShading · (1 - light) on top of the
/// variation. Does nothing when \p variation is not active and no light shading is asked.
void tintLeafCards(Mesh& mesh, std::size_t firstVertex, const LeafColorVariation& variation,
                   const glm::vec3& referenceSrgb, double patchSize, std::uint64_t seed,
                   std::span<const float> cardLight = {}, double lightShading = 0.0);

/// Linear 0..1 to an sRGB 0..1 value, and back (IEC 61966-2-1).
float linearToSrgb(float linear);
float srgbToLinear(float srgb);
/// A Mesh::colors channel (linear, 255 = 1) as sRGB 0..1: what FBX and OBJ readers expect.
inline float srgbFromByte(std::uint8_t linear) {
    return linearToSrgb(static_cast<float>(linear) / 255.0f);
}

} // namespace sylva::mesh
