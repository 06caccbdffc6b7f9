#include "engine/growth/litattractors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

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

/// Candidate cluster centres in index order, struct of arrays: the squared distance to the
/// nearest centre chosen so far kept up to date four points at a time (SSE2 rounds as the
/// scalar code did), the scores made four at a time, the best taken in order.
class Candidates {
public:
    void add(const glm::vec3& p, float weight, float jitter) {
        mX.push_back(p.x);
        mY.push_back(p.y);
        mZ.push_back(p.z);
        mWeight.push_back(weight);
        mJitter.push_back(jitter);
        mNearest.push_back(std::numeric_limits<float>::max());
    }
    std::size_t size() const { return mX.size(); }
    glm::vec3 point(std::size_t k) const { return {mX[k], mY[k], mZ[k]}; }

    /// nearest = min(nearest, |p - centre|^2), as glm::dot(d, d) sums it.
    void closer(const glm::vec3& centre) {
        for (std::size_t k = 0; k < mX.size(); ++k) {
            const float dx = mX[k] - centre.x, dy = mY[k] - centre.y, dz = mZ[k] - centre.z;
            mNearest[k] = std::min(mNearest[k], (dx * dx + dy * dy) + dz * dz);
        }
    }

    /// The first candidate of the highest score (size() when none beats -1): score =
    /// weight x spread x jitter (weighted) or spread x jitter, spread = sqrt(nearest) or 1.
    std::size_t best(bool spread, bool weighted) {
        const std::size_t n = mX.size();
        mScore.resize(n);
        std::size_t k = 0;
#if defined(__SSE2__)
        const __m128 one = _mm_set1_ps(1.0f);
        for (; k + 4 <= n; k += 4) {
            const __m128 s = spread ? _mm_sqrt_ps(_mm_loadu_ps(&mNearest[k])) : one;
            const __m128 w = weighted ? _mm_mul_ps(_mm_loadu_ps(&mWeight[k]), s) : s;
            _mm_storeu_ps(&mScore[k], _mm_mul_ps(w, _mm_loadu_ps(&mJitter[k])));
        }
#endif
        for (; k < n; ++k) {
            const float s = spread ? std::sqrt(mNearest[k]) : 1.0f;
            mScore[k] = (weighted ? mWeight[k] * s : s) * mJitter[k];
        }
        std::size_t best = n;
        float bestScore = -1.0f;
        for (k = 0; k < n; ++k)
            if (mScore[k] > bestScore) {
                bestScore = mScore[k];
                best = k;
            }
        return best;
    }

private:
    std::vector<float> mX, mY, mZ, mWeight, mJitter, mNearest, mScore;
};

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
        // Each point's eligibility (the lit half of its band for an outer centre, the shaded
        // inside that is not shed for an inner one) and sqrt(exposure), made once, not once a
        // centre; the centres are chosen among the eligible points in index order by the same
        // score expression and the same strict '>' (the same centres, bit for bit).
        Candidates outer, inner;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const float m = median[bandOf(points[i])];
            if (shadow[i] <= m)
                outer.add(points[i], std::sqrt(exposure[i]), jitter[i]);
            else if (shadow[i] < shedAbove)
                inner.add(points[i], 1.0f, jitter[i]);
        }
        const std::size_t k = std::min(points.size(), static_cast<std::size_t>(params.clusters));
        for (std::size_t c = 0; c < k; ++c) {
            const std::size_t best = outer.best(!centres.empty(), true);
            const glm::vec3 centre = best < outer.size() ? outer.point(best) : points[0];
            centres.push_back(centre);
            radii.push_back(params.clusterRadius * halfExtent *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            outer.closer(centre);
            inner.closer(centre);
        }
        // Inner clusters: among the shaded inside that is not shed, as far from every centre
        // as possible, so the limbs carry foliage through the depth of the crown.
        const float innerR = params.innerRadius * params.clusterRadius * halfExtent;
        for (int c = 0; c < innerCount; ++c) {
            const std::size_t best = inner.best(true, false);
            if (best == inner.size()) break;
            const glm::vec3 centre = inner.point(best);
            centres.push_back(centre);
            radii.push_back(innerR *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            outer.closer(centre);
            inner.closer(centre);
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
