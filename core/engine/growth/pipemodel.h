#pragma once

#include "engine/skeleton/skeleton.h"

namespace sylva::growth {

/// Smallest and largest pipe-model exponent accepted. 1 adds radii (a trunk as wide as all tips
/// together), 2 preserves cross-section area (Leonardo's rule), 2–3 is what measured trees show
/// (MacDonald; the reference's "invert growth" 2.41); above 4 every branch looks alike.
inline constexpr float kMinPipeExponent = 1.0f;
inline constexpr float kMaxPipeExponent = 4.0f;

/// Sets every radius of \p skeleton by the pipe model: a node without visible children gets
/// \p tipRadius, every other node r with r^e = Σ r_child^e over its children that are not
/// kHidden (hidden nodes still get a radius, they just do not feed their parent). One reverse
/// linear scan (parents are stored before children); sums run in double.
/// \param tipRadius metres, in (0, 10]
/// \param exponent e, in [kMinPipeExponent, kMaxPipeExponent]
/// \throw InvalidInput for a value out of range or an invalid skeleton.
void applyPipeModel(skel::Skeleton& skeleton, float tipRadius, float exponent);

} // namespace sylva::growth
