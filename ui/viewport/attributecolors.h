#pragma once

#include <vector>

#include <QString>

#include <glm/glm.hpp>

namespace sylva::mesh {
struct Mesh;
}
namespace sylva::skel {
struct Skeleton;
}

namespace sylva::ui {

/// What the viewport colours a tree by: its materials, or a per-node attribute of the skeleton
/// mapped to a colour ramp (self-organizing trees carry light, vigour and age; every skeleton
/// has branch order).
enum class ColorBy {
    Material,
    Light,       ///< light per internode of the node's subtree: the quantity shedding tests;
                 ///< branches below the shedding threshold (skel::kStarved) in kStarvedColor
    Vigour,      ///< resource flowing through the node (log scale)
    Age,         ///< growth cycles since the node's metamer grew
    BranchOrder, ///< 0 for the trunk
};

/// Whether \p skeleton carries what \p mode shows (Material and BranchOrder always do).
bool hasAttribute(const skel::Skeleton& skeleton, ColorBy mode);

/// The attribute of every node, scaled to 0..1 for the ramp (see ColorBy), or empty when the
/// skeleton lacks it. Light: light / (metamers in the subtree), divided by its largest value;
/// vigour: log(1 + v) / log(1 + v_max); age and order: value / largest value.
std::vector<float> normalizedAttribute(const skel::Skeleton& skeleton, ColorBy mode);

/// Colour (linear RGB) of starved nodes when colouring by light: the branches the next growth
/// cycle would shed. Red, outside the ramp's blue–green–yellow.
inline constexpr glm::vec3 kStarvedColor{0.80f, 0.02f, 0.02f};

/// The colour ramp (linear RGB): dark blue (0) through teal and green to yellow (1), readable on
/// the viewport's background and monotonic in brightness.
glm::vec3 rampColor(float t);

/// Per-vertex linear colours for \p mesh (Mesh::node must be filled), empty when the mode is
/// Material or the data is missing. Vertices of unknown nodes get the ramp's 0.
std::vector<glm::vec3> attributeColors(const mesh::Mesh& mesh, const skel::Skeleton& skeleton,
                                       ColorBy mode);

/// The legend shown in the status bar, e.g. "Light per internode: 0 (blue) – 0.82 (yellow)";
/// for light with a shedding threshold it adds how many internodes are starved (red) and the
/// threshold they fall below.
QString attributeLegend(const skel::Skeleton& skeleton, ColorBy mode);

/// attributeColors() and attributeLegend() together, from one pass over the skeleton (what the
/// viewport shows after each generation).
struct AttributeColoring {
    std::vector<glm::vec3> colors;
    QString legend;
};
AttributeColoring colorByAttribute(const mesh::Mesh& mesh, const skel::Skeleton& skeleton,
                                   ColorBy mode);

} // namespace sylva::ui
