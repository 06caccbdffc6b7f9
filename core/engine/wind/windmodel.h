#pragma once

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"

namespace sylva::wind {

/// The wind a tree stands in (docs/wind.md). Every consumer (the per-vertex shader data, the
/// baked clip, the viewport's vertex shader) evaluates the same model with these.
/// The allowed range of a wind setting: the one place it is stated (validate(), the project's
/// settings spec core/document/projectsettings.h, the Properties panel, Python and the CLI).
struct WindRange {
    double lo, hi;
};
inline constexpr WindRange kStrengthRange{0.0, 2.0}, kGustinessRange{0.0, 1.0},
    kFrequencyRange{0.05, 5.0}, kPeriodRange{0.5, 600.0};

struct WindSettings {
    glm::vec3 direction{1.0f, 0.0f, 0.0f}; ///< where the wind blows to; only x and z count
    float strength = 0.5f;                 ///< 0 (calm) .. 2 (storm); bending grows with its square
    float gustiness = 0.3f;                ///< 0 (steady) .. 1 (gusts double the mean pressure)
    float frequency = 0.5f; ///< Hz of the trunk's sway, 0.05 .. 5; limbs and leaves go faster
    /// Seconds after which the motion repeats exactly (a baked clip's length): every frequency
    /// of the model is a whole multiple of 1 / period. 0.5 .. 600.
    float period = 4.0f;
    bool operator==(const WindSettings&) const = default;
};

/// Throws InvalidInput naming the allowed range of a setting outside it.
void validate(const WindSettings& settings);

/// The wind's horizontal unit direction (x, 0, z); +X when the direction has no horizontal part.
glm::vec3 horizontalDirection(const WindSettings& settings);

/// The time-dependent part of the model for one time: what the shader receives as uniforms.
struct WindFrame {
    glm::vec3 direction{1, 0, 0}; ///< horizontal unit
    float strength = 0.0f;
    float gustiness = 0.0f;
    float time = 0.0f;       ///< seconds, reduced modulo the period
    float omega = 0.0f;      ///< 2π / period
    float baseCycles = 1.0f; ///< the trunk's cycles per period (a whole number ≥ 1)
};
WindFrame windFrame(const WindSettings& settings, double seconds);

/// Stiffness of a sway element (dimensionless; its bend per unit pressure is 1 / stiffness) from
/// its hierarchy level (0..2), base radius and length (m): thick, short elements are stiffer.
float elementStiffness(int level, float radius, float length);

/// The rotation vector (axis × angle, radians) at the tip (u = 1) of an element of unit
/// direction \p dir, \p stiffness, \p phase (0..1) and \p level at \p frame; a point at bend
/// fraction u turns by bendProfile(u) times it about the element's pivot.
glm::vec3 elementRotation(const WindFrame& frame, const glm::vec3& dir, float stiffness,
                          float phase, int level, float treePhase);

/// How much of the tip's rotation a point at fraction \p u (0 base .. 1 tip) of an element
/// takes: u (2 − u), the slope of a cantilever under a load at its tip.
inline float bendProfile(float u) {
    return u * (2.0f - u);
}

/// \p v rotated by the rotation vector \p r (Rodrigues).
glm::vec3 rotate(const glm::vec3& r, const glm::vec3& v);

/// Where a vertex of rest position \p position and normal \p normal is at \p frame: the leaf
/// flutter along the normal, then the element bends from the innermost level out (each about its
/// rest pivot, so a child follows its parent and nothing tears at a fork), then no lower than
/// the tree's base (the level-0 pivot) unless it rested lower. \p normal is turned with it.
/// This is the function the viewport's shader (ui/viewport/shaders/wind.glsl) repeats.
glm::vec3 displace(const mesh::WindVertex& w, const glm::vec3& position, glm::vec3* normal,
                   const WindFrame& frame);

} // namespace sylva::wind
