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

/// static_cast<float>(std::pow(x, 0.5)) for a finite \p x > 0, mostly without pow: the
/// correctly rounded square root s, taken where every double within four steps of s rounds to
/// the same float (pow's result is within 1 ulp of the true root, s within half an ulp, so pow's
/// is one of those doubles and, rounding being monotone, rounds to that float too); pow where
/// they do not (about once in 10^7 for random x). The pipe model's radius for the exponent 2.
float floatSquareRoot(double x);

} // namespace sylva::growth
