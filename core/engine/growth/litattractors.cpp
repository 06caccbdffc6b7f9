#include "engine/growth/litattractors.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "engine/growth/litcandidates.h"
#include "engine/growth/shadowcounts.h"
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

/// A point's shadow from its voxel's fixed-point value, as ShadowGrid::shadow() makes it.
float shadowOf(std::int32_t raw) {
    return static_cast<float>(raw / ShadowGrid::kScale - kShadowA);
}

/// lo = glm::min(lo, p), hi = glm::max(hi, p) over the points from +-float max: on SSE2 the
/// three coordinates in one register, the same comparisons in the same order (minps(p, lo) is
/// p < lo ? p : lo, glm::min's choice; maxps(p, hi) is hi < p ? p : hi, glm::max's).
void bounds(const std::vector<glm::vec3>& points, glm::vec3& lo, glm::vec3& hi) {
    lo = glm::vec3(std::numeric_limits<float>::max());
    hi = glm::vec3(-std::numeric_limits<float>::max());
#if defined(__SSE2__)
    __m128 l = _mm_set1_ps(lo.x), h = _mm_set1_ps(hi.x);
    for (const glm::vec3& p : points) {
        const __m128 xy = _mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&p.x));
        const __m128 q = _mm_movelh_ps(xy, _mm_load_ss(&p.z));
        l = _mm_min_ps(q, l);
        h = _mm_max_ps(q, h);
    }
    alignas(16) float lv[4], hv[4];
    _mm_store_ps(lv, l);
    _mm_store_ps(hv, h);
    lo = {lv[0], lv[1], lv[2]};
    hi = {hv[0], hv[1], hv[2]};
#else
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
#endif
}

/// sqrt(exposure) of every point, exposure = 1 / (1 + max(shadow, 0)), four at a time on
/// SSE2: the same divisions and square roots, correctly rounded in every lane.
std::vector<float> sqrtExposure(const std::vector<float>& shadow) {
    const std::size_t n = shadow.size();
    std::vector<float> out(n);
    std::size_t i = 0;
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    for (; i + 4 <= n; i += 4) {
        // maxps(0, s) = 0 > s ? 0 : s, std::max(s, 0.0f) exactly.
        const __m128 m = _mm_max_ps(zero, _mm_loadu_ps(&shadow[i]));
        _mm_storeu_ps(&out[i], _mm_sqrt_ps(_mm_div_ps(one, _mm_add_ps(one, m))));
    }
#endif
    for (; i < n; ++i)
        out[i] = std::sqrt(1.0f / (1.0f + std::max(shadow[i], 0.0f)));
    return out;
}

/// Order statistics of the points' fixed-point shadows: the value of rank r (the (r+1)-th
/// smallest) of all of them and of each height band's. shadowOf() does not decrease, so
/// shadowOf(the rank r value) is the rank r shadow: the float values std::nth_element over
/// the shadows gave. The values are sums of the kernel's increments, all multiples of
/// 2^shift: where they span few multiples they are counted (a histogram per band and one of
/// all), otherwise std::nth_element picks them from a copy.
class ShadowRanks {
public:
    ShadowRanks(const std::vector<std::int32_t>& raw, const std::vector<std::uint8_t>& band,
                int bands, int shift)
        : mRaw(raw), mBand(band), mShift(shift) {
        std::int32_t top = 0, bottom = 0;
        for (const std::int32_t r : raw) {
            top = std::max(top, r);
            bottom = std::min(bottom, r);
        }
        const std::size_t units = (static_cast<std::size_t>(top) >> shift) + 1;
        // A histogram no larger than a few times the points and 65,536 steps (9 x 256 KiB at
        // most; the oak's 5,000 points span ~500 steps).
        if (bottom < 0 || units > std::min<std::size_t>(4 * raw.size() + 4096, 65536)) return;
        mUnits = units;
        const std::size_t groups = band.empty() ? 1 : static_cast<std::size_t>(bands) + 1;
        mCounts.assign(groups * units, 0);
        std::uint32_t* all = mCounts.data() + (groups - 1) * units;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            const auto u = static_cast<std::size_t>(raw[i]) >> shift;
            ++all[u];
            if (!band.empty()) ++mCounts[band[i] * units + u];
        }
    }
    /// Rank \p rank among all points (rank < their count).
    std::int32_t all(std::size_t rank) const {
        if (mUnits == 0) {
            std::vector<std::int32_t> copy = mRaw;
            return select(copy, rank);
        }
        const std::size_t groups = mCounts.size() / mUnits;
        return counted(mCounts.data() + (groups - 1) * mUnits, rank);
    }
    /// Rank \p rank among the points of band \p b (rank < their count).
    std::int32_t inBand(int b, std::size_t rank) const {
        if (mUnits == 0) {
            std::vector<std::int32_t> copy;
            for (std::size_t i = 0; i < mRaw.size(); ++i)
                if (mBand[i] == b) copy.push_back(mRaw[i]);
            return select(copy, rank);
        }
        return counted(mCounts.data() + static_cast<std::size_t>(b) * mUnits, rank);
    }

private:
    static std::int32_t select(std::vector<std::int32_t>& v, std::size_t rank) {
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(rank), v.end());
        return v[rank];
    }
    std::int32_t counted(const std::uint32_t* counts, std::size_t rank) const {
        std::size_t seen = 0;
        for (std::size_t u = 0; u < mUnits; ++u) {
            seen += counts[u];
            if (seen > rank) return static_cast<std::int32_t>(u << mShift);
        }
        return static_cast<std::int32_t>((mUnits - 1) << mShift); // rank beyond the count
    }

    const std::vector<std::int32_t>& mRaw;
    const std::vector<std::uint8_t>& mBand;
    int mShift;
    std::size_t mUnits = 0; ///< 0: no histogram, nth_element
    std::vector<std::uint32_t> mCounts;
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

    glm::vec3 lo, hi;
    bounds(points, lo, hi);
    const float halfExtent = std::max((hi.x - lo.x + hi.y - lo.y + hi.z - lo.z) / 6.0f, 1e-3f);

    // Shadow of the others at each point's voxel (integer pyramids: order-independent), counted
    // at the points (shadowAtSources: the grid's values there, bit for bit) unless the grid
    // must decide (a box that could reach its limit).
    const ShadowKernel kernel = ShadowKernel::make(kShadowA, kShadowB, kShadowDepth);
    ShadowGrid grid(params.voxelSize, lo.y - params.voxelSize, kShadowDepth);
    std::vector<ShadowSource> sources(points.size());
    grid.voxelsOf(points, sources);
    const std::size_t n = points.size();
    std::vector<glm::ivec3> voxels(n);
    for (std::size_t i = 0; i < n; ++i)
        voxels[i] = sources[i].voxel;
    std::vector<std::int32_t> raw;
    if (!shadowAtSources(voxels, kernel, raw)) {
        grid.applyBatch(sources, std::span<const ShadowKernel>(&kernel, 1));
        raw.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            raw[i] = grid.raw(sources[i].voxel);
    }
    std::vector<float> shadow(n);
    for (std::size_t i = 0; i < n; ++i)
        shadow[i] = shadowOf(raw[i]);
    // Every value is a sum of the kernel's increments: a multiple of their lowest power of two.
    int shift = 31;
    for (const std::int32_t d : kernel.delta)
        shift = std::min(shift, std::countr_zero(static_cast<std::uint32_t>(d)));

    // Height bands (below) exist with clusters only.
    constexpr int kBands = 8;
    std::vector<std::uint8_t> band;
    if (params.clusters > 0) {
        const float bandHeight = std::max((hi.y - lo.y) / kBands, 1e-6f);
        band.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            band[i] = static_cast<std::uint8_t>(
                std::clamp(static_cast<int>((points[i].y - lo.y) / bandHeight), 0, kBands - 1));
    }
    const ShadowRanks ranks(raw, band, kBands, shift);

    // The shadow above which a point is shed: the (1 - shadedFraction) quantile.
    float shedAbove = std::numeric_limits<float>::max();
    if (params.shadedFraction > 0.0f) {
        const std::size_t keep = static_cast<std::size_t>(
            std::floor((1.0 - params.shadedFraction) * static_cast<double>(n)));
        if (keep < n) shedAbove = shadowOf(ranks.all(keep));
    }

    // Each point's lit flag (within some cluster's radius), set by the candidates' visits.
    // Without clusters every point is lit (only the shedding drops points).
    std::vector<std::uint8_t> lit(n, params.clusters > 0 ? 0 : 1);
    if (params.clusters > 0) {
        Rng rng(mixSeed(seed, salt::kLitAttractors));
        std::vector<float> jitter(n);
        for (float& j : jitter)
            j = rng.uniformf(0.75f, 1.0f);
        // Centres only on the lit half of each height band (the sky's light comes from the side
        // too): a cluster inside the shaded crown would be foliage where no light reaches (it also
        // grows a tuft at the trunk's fork), while the lower sides of a narrow crown are lit.
        std::array<std::size_t, kBands> bandCount{};
        for (const std::uint8_t b : band)
            ++bandCount[b];
        std::array<float, kBands> median{};
        for (int b = 0; b < kBands; ++b)
            if (bandCount[b] > 0) median[b] = shadowOf(ranks.inBand(b, bandCount[b] / 2));
        // Each point's eligibility (the lit half of its band for an outer centre, the shaded
        // inside that is not shed for an inner one) and sqrt(exposure), made once, not once a
        // centre; the centres are chosen among the eligible points in index order by the same
        // score expression and the same strict '>' (the same centres, bit for bit).
        // Exposure in (0, 1]: 1 unshaded, falling with the shadow (Palubicki's Q = max(C - s + a,
        // 0) would be 0 for most of a dense crown's inside; a ratio keeps the order among them).
        const std::vector<float> weight = sqrtExposure(shadow);
        LitCandidates outer(n), inner(n);
        for (std::size_t i = 0; i < n; ++i) {
            const bool isOuter = shadow[i] <= median[band[i]];
            outer.offer(isOuter, points[i], weight[i], jitter[i], i);
            // '&' on ints, not '&&': no branch on isOuter (about half the points either way).
            inner.offer((static_cast<int>(!isOuter) & static_cast<int>(shadow[i] < shedAbove)) != 0,
                        points[i], 1.0f, jitter[i], i);
        }
        const std::size_t k = std::min(n, static_cast<std::size_t>(params.clusters));
        // Each centre's visit scores the candidates for the next one. The distances are kept
        // while a later score needs them; the lit flags are set by every visit.
        std::size_t best = outer.best(CandidateScore::Weight);
        for (std::size_t c = 0; c < k; ++c) {
            const glm::vec3 centre = best < outer.size() ? outer.point(best) : points[0];
            const float r = params.clusterRadius * halfExtent *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f));
            best = outer.visit(centre, r * r,
                               c + 1 < k ? CandidateVisit::WeightedSpread : CandidateVisit::Lit);
            inner.visit(centre, r * r,
                        innerCount > 0 ? CandidateVisit::Nearest : CandidateVisit::Lit);
        }
        // Inner clusters: among the shaded inside that is not shed, as far from every centre
        // as possible, so the limbs carry foliage through the depth of the crown.
        const float innerR = params.innerRadius * params.clusterRadius * halfExtent;
        best = innerCount > 0 ? inner.best(CandidateScore::Spread) : inner.size();
        for (int c = 0; c < innerCount && best < inner.size(); ++c) {
            const glm::vec3 centre = inner.point(best);
            const float r =
                innerR * (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f));
            outer.visit(centre, r * r, CandidateVisit::Lit);
            best = inner.visit(centre, r * r,
                               c + 1 < innerCount ? CandidateVisit::Spread : CandidateVisit::Lit);
        }
        outer.markLit(lit);
        inner.markLit(lit);
    }

    // Every point written, the kept ones counted (a branch here would be mispredicted often).
    std::vector<glm::vec3> kept(n + 1);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        kept[m] = points[i];
        m += static_cast<std::size_t>(static_cast<int>(shadow[i] < shedAbove) & lit[i]);
    }
    kept.resize(m);
    return kept;
}

} // namespace sylva::growth
