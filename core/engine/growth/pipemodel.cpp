#include "engine/growth/pipemodel.h"

#include <cmath>
#include <vector>

#include "engine/util/error.h"

namespace sylva::growth {

void applyPipeModel(skel::Skeleton& skeleton, float tipRadius, float exponent) {
    requireRange("tip_radius", tipRadius, 0.0, 10.0);
    if (!(tipRadius > 0.0f)) throw InvalidInput("tip_radius must be > 0, got 0");
    requireRange("pipe_exponent", exponent, kMinPipeExponent, kMaxPipeExponent);
    skeleton.validate();

    const double e = exponent;
    std::vector<double> sum(skeleton.size(), 0.0);
    for (std::size_t k = skeleton.size(); k-- > 0;) {
        const float r = sum[k] > 0.0 ? static_cast<float>(std::pow(sum[k], 1.0 / e)) : tipRadius;
        skeleton.radius[k] = r;
        const std::int32_t p = skeleton.parent[k];
        if (p >= 0 && (skeleton.flags[k] & skel::kHidden) == 0)
            sum[static_cast<std::size_t>(p)] += std::pow(static_cast<double>(r), e);
    }
}

} // namespace sylva::growth
