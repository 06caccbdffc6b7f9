#pragma once

#include "engine/skeleton/skeleton.h"

namespace sylva::skel {

/// The final radius pass every generator node runs on its skeleton (issue #44: one continuous
/// tree), so that meshes, LODs, exporters, metrics and the wind all see the same radii.
struct RadiusShaping {
    /// Least taper of an axis, per metre: going down an axis, a node is at least
    /// (1 + taper · segment length) times as thick as the node above it, so a stretch without
    /// branches (a clear trunk, which the pipe model leaves a cylinder) still tapers. 1/m,
    /// [0, 1]; 0: off.
    float taper = 0.1f;
    /// Steepest fall of the radius along an axis above a fork, metres per metre (the tangent
    /// of the half-angle of the cone): the axis that goes on from a fork keeps close to the
    /// radius below it and thins at most this fast, instead of showing a step or a collar
    /// where a big branch leaves. [0, 10]; 0: off.
    float junctionSlope = 0.08f;
};

/// Throws InvalidInput for a value out of range.
void validate(const RadiusShaping& shaping);

/// Shapes the radii of \p skeleton, in three linear scans (parents are stored first):
/// 1. every axis that ends at a fork goes on in its thickest visible child (ties: the lower
///    index), which takes the parent's branch order with its whole axis; the other children
///    start axes one order higher (so no trunk ends at a fork with a flat cap wider than the
///    branches above it);
/// 2. from the tips down, each node is at least (1 + taper · length) times its continuing
///    child's radius;
/// 3. from the root up, no node is thicker than its parent, and a continuing child is at least
///    its parent's radius less junctionSlope · length.
/// Hidden nodes keep their radius and feed nothing. Deterministic; positions are untouched.
/// \throw InvalidInput for bad settings or an invalid skeleton.
void shapeRadii(Skeleton& skeleton, const RadiusShaping& shaping = {});

} // namespace sylva::skel
