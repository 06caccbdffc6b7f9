#include "engine/growth/pipemodel.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/util/error.h"

namespace sylva::growth {

float floatSquareRoot(double x) {
    const double s = std::sqrt(x);
    // Positive doubles order as their bit patterns: four steps down and up, across binades too.
    const auto bits = std::bit_cast<std::uint64_t>(s);
    const auto lo = static_cast<float>(std::bit_cast<double>(bits - 4));
    const auto hi = static_cast<float>(std::bit_cast<double>(bits + 4));
    return lo == hi ? lo : static_cast<float>(std::pow(x, 0.5));
}

void applyPipeModel(skel::Skeleton& skeleton, float tipRadius, float exponent) {
    requireRange("tip_radius", tipRadius, 0.0, 10.0);
    if (!(tipRadius > 0.0f)) throw InvalidInput("tip_radius must be > 0, got 0");
    requireRange("pipe_exponent", exponent, kMinPipeExponent, kMaxPipeExponent);
    skeleton.validate();

    const double e = exponent;
    // r^e without most of the pow calls (two a node were most of this pass): a tip's is the
    // same every time, and with the usual exponent 2 the float radius squared in double is
    // exact, so pow (within 0.52 ulp in glibc, with well under 0.1 ulp of it before the
    // rounding) returns exactly r * r too: the sums and radii are the same bits. The radius
    // pow(sum, 1 / 2) by floatSquareRoot: a square root (a pow a node was ~0.7 % of the oak's
    // samples, a twentieth of its colonization), the same floats.
    const double tipPower = std::pow(static_cast<double>(tipRadius), e);
    const bool square = e == 2.0;
    std::vector<double> sum(skeleton.size(), 0.0);
    for (std::size_t k = skeleton.size(); k-- > 0;) {
        const bool tip = !(sum[k] > 0.0);
        const float r = tip      ? tipRadius
                        : square ? floatSquareRoot(sum[k])
                                 : static_cast<float>(std::pow(sum[k], 1.0 / e));
        skeleton.radius[k] = r;
        const std::int32_t p = skeleton.parent[k];
        if (p >= 0 && (skeleton.flags[k] & skel::kHidden) == 0) {
            const auto rd = static_cast<double>(r);
            sum[static_cast<std::size_t>(p)] += tip ? tipPower : square ? rd * rd : std::pow(rd, e);
        }
    }
}

} // namespace sylva::growth
