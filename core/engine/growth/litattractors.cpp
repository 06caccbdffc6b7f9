#include "engine/growth/litattractors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/growth/shadowgrid.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::growth {

namespace {

void requireIn(const char* name, double v, double lo, double hi, bool openLow) {
    const bool ok = (openLow ? v > lo : v >= lo) && v <= hi;
    if (!ok)
        throw InvalidInput(std::string("light.") + name + " must be in " + (openLow ? "(" : "[") +
                           std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                           std::to_string(v));
}

// Palubicki et al.'s pyramid: a = 1 at the source voxel, halved each voxel further down.
constexpr double kShadowA = 1.0;
constexpr double kShadowB = 2.0;
constexpr int kShadowDepth = 4;

} // namespace

void validate(const LightParams& p) {
    requireIn("clusters", p.clusters, 0, 1000, false);
    requireIn("cluster_radius", p.clusterRadius, 0, 2, true);
    requireIn("cluster_spread", p.clusterSpread, 0, 1, false);
    requireIn("shaded_fraction", p.shadedFraction, 0, 1, false);
    if (p.shadedFraction >= 1.0f)
        throw InvalidInput("light.shaded_fraction must be in [0, 1), got " +
                           std::to_string(p.shadedFraction));
    requireIn("voxel_size", p.voxelSize, 0, 100, true);
    requireIn("inner_clusters", p.innerClusters, 0, 1000, false);
    requireIn("inner_radius", p.innerRadius, 0, 2, true);
}

std::vector<glm::vec3> litAttractors(const std::vector<glm::vec3>& points,
                                     const LightParams& params, std::uint64_t seed) {
    validate(params);
    if (points.empty() || (params.clusters == 0 && params.shadedFraction <= 0.0f)) return points;
    // Inner clusters only make sense inside a crown of lit clusters.
    const int innerCount = params.clusters > 0 ? params.innerClusters : 0;

    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float halfExtent = std::max((hi.x - lo.x + hi.y - lo.y + hi.z - lo.z) / 6.0f, 1e-3f);

    // Shadow of the others at each point's voxel (integer pyramids: order-independent).
    const ShadowKernel kernel = ShadowKernel::make(kShadowA, kShadowB, kShadowDepth);
    ShadowGrid grid(params.voxelSize, lo.y - params.voxelSize, kShadowDepth);
    std::vector<ShadowSource> sources(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        sources[i].voxel = grid.voxelOf(points[i]);
    grid.applyBatch(sources, std::span<const ShadowKernel>(&kernel, 1));
    std::vector<float> shadow(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        shadow[i] = static_cast<float>(grid.shadow(sources[i].voxel) - kShadowA);
    }
    // Exposure in (0, 1]: 1 unshaded, falling with the shadow (Palubicki's Q = max(C - s + a, 0)
    // would be 0 for most of a dense crown's inside; a ratio keeps the order among them).
    std::vector<float> exposure(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        exposure[i] = 1.0f / (1.0f + std::max(shadow[i], 0.0f));

    // The shadow above which a point is shed: the (1 - shadedFraction) quantile.
    float shedAbove = std::numeric_limits<float>::max();
    if (params.shadedFraction > 0.0f) {
        std::vector<float> sorted = shadow;
        const std::size_t keep = static_cast<std::size_t>(
            std::floor((1.0 - params.shadedFraction) * static_cast<double>(sorted.size())));
        if (keep < sorted.size()) {
            std::nth_element(sorted.begin(), sorted.begin() + keep, sorted.end());
            shedAbove = sorted[keep];
        }
    }

    std::vector<glm::vec3> centres;
    std::vector<float> radii;
    if (params.clusters > 0) {
        Rng rng(mixSeed(seed, salt::kLitAttractors));
        std::vector<float> jitter(points.size());
        for (float& j : jitter)
            j = rng.uniformf(0.75f, 1.0f);
        // Centres only on the lit half of each height band (the sky's light comes from the side
        // too): a cluster inside the shaded crown would be foliage where no light reaches (it also
        // grows a tuft at the trunk's fork), while the lower sides of a narrow crown are lit.
        constexpr int kBands = 8;
        const float bandHeight = std::max((hi.y - lo.y) / kBands, 1e-6f);
        auto bandOf = [&](const glm::vec3& p) {
            return std::clamp(static_cast<int>((p.y - lo.y) / bandHeight), 0, kBands - 1);
        };
        std::vector<std::vector<float>> bands(kBands);
        for (std::size_t i = 0; i < points.size(); ++i)
            bands[bandOf(points[i])].push_back(shadow[i]);
        std::vector<float> median(kBands, 0.0f);
        for (int b = 0; b < kBands; ++b) {
            std::vector<float>& v = bands[b];
            if (v.empty()) continue;
            std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
            median[b] = v[v.size() / 2];
        }
        // Each point's band, its eligibility for an outer centre (lit half of its band) and
        // for an inner one, and sqrt(exposure), made once, not once a centre: the centres are
        // chosen among the eligible points only, in index order, by the same score expression
        // and the same strict '>' (the same centres, bit for bit). `nearest` is kept for every
        // point (the inner centres read it).
        std::vector<std::uint32_t> outer, inner;
        std::vector<float> rootExposure(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const float m = median[bandOf(points[i])];
            rootExposure[i] = std::sqrt(exposure[i]);
            if (shadow[i] <= m)
                outer.push_back(static_cast<std::uint32_t>(i));
            else if (shadow[i] < shedAbove)
                inner.push_back(static_cast<std::uint32_t>(i));
        }
        std::vector<float> nearest(points.size(), std::numeric_limits<float>::max());
        auto closer = [&](const glm::vec3& centre) {
            for (std::size_t i = 0; i < points.size(); ++i) {
                const glm::vec3 d = points[i] - centre;
                nearest[i] = std::min(nearest[i], glm::dot(d, d));
            }
        };
        const std::size_t k = std::min(points.size(), static_cast<std::size_t>(params.clusters));
        for (std::size_t c = 0; c < k; ++c) {
            std::size_t best = 0;
            float bestScore = -1.0f;
            for (std::uint32_t i : outer) {
                const float spread = centres.empty() ? 1.0f : std::sqrt(nearest[i]);
                const float score = rootExposure[i] * spread * jitter[i];
                if (score > bestScore) {
                    bestScore = score;
                    best = i;
                }
            }
            centres.push_back(points[best]);
            radii.push_back(params.clusterRadius * halfExtent *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            closer(points[best]);
        }
        // Inner clusters: among the shaded inside that is not shed, as far from every centre
        // as possible, so the limbs carry foliage through the depth of the crown.
        const float innerR = params.innerRadius * params.clusterRadius * halfExtent;
        for (int c = 0; c < innerCount; ++c) {
            std::size_t best = points.size();
            float bestScore = -1.0f;
            for (std::uint32_t i : inner) {
                const float score = std::sqrt(nearest[i]) * jitter[i];
                if (score > bestScore) {
                    bestScore = score;
                    best = i;
                }
            }
            if (best == points.size()) break;
            centres.push_back(points[best]);
            radii.push_back(innerR *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            closer(points[best]);
        }
    }

    std::vector<glm::vec3> kept;
    kept.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (shadow[i] >= shedAbove) continue;
        bool lit = centres.empty();
        for (std::size_t c = 0; c < centres.size() && !lit; ++c) {
            const glm::vec3 d = points[i] - centres[c];
            lit = glm::dot(d, d) <= radii[c] * radii[c];
        }
        if (lit) kept.push_back(points[i]);
    }
    return kept;
}

} // namespace sylva::growth
