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

/// What Candidates::visit scores after its distance update.
enum class Score { None, Spread, WeightedSpread };

/// Candidate cluster centres in index order, struct of arrays. Each centre chosen is visited
/// once: every candidate's squared distance to it (summed as glm::dot sums it) lowers the
/// distance to the nearest centre and marks the candidate lit when it is within that centre's
/// radius, and the same pass scores the candidates for the next centre and keeps the first of
/// the highest score, four at a time on SSE2 (each lane rounds as the scalar code does).
class Candidates {
public:
    /// Room for \p capacity candidates (one more slot: an offer always writes).
    explicit Candidates(std::size_t capacity)
        : mX(capacity + 1), mY(capacity + 1), mZ(capacity + 1), mWeight(capacity + 1),
          mJitter(capacity + 1), mNearest(capacity + 1, std::numeric_limits<float>::max()),
          mLit(capacity + 1, 0), mIndex(capacity + 1) {}
    /// Appends the point when \p take; written either way, so that choosing between the
    /// outer and the inner candidates (about half and half) takes no branch.
    void offer(bool take, const glm::vec3& p, float weight, float jitter, std::size_t index) {
        mX[mCount] = p.x;
        mY[mCount] = p.y;
        mZ[mCount] = p.z;
        mWeight[mCount] = weight;
        mJitter[mCount] = jitter;
        mIndex[mCount] = static_cast<std::uint32_t>(index);
        mCount += take ? 1 : 0;
    }
    std::size_t size() const { return mCount; }
    glm::vec3 point(std::size_t k) const { return {mX[k], mY[k], mZ[k]}; }

    /// The first candidate of the highest score (size() when none beats -1) without a visit:
    /// score = weight x spread x jitter (weighted) or spread x jitter, spread = sqrt(nearest)
    /// (Score::Spread, Score::WeightedSpread) or 1 (Score::None, weighted).
    std::size_t best(Score score) const {
        Best b;
        for (std::size_t k = 0; k < mCount; ++k)
            b.offer(scoreOf(k, score), k);
        return b.index(mCount);
    }

    /// A centre chosen, of squared radius \p r2: nearest = min(nearest, |p - centre|^2), lit
    /// when |p - centre|^2 <= r2; then best(score) of the updated distances (size() for
    /// Score::None, which scores nothing).
    std::size_t visit(const glm::vec3& centre, float r2, Score score) {
        const std::size_t n = mCount;
        std::size_t k = 0;
        Best b;
#if defined(__SSE2__)
        const __m128 cx = _mm_set1_ps(centre.x), cy = _mm_set1_ps(centre.y),
                     cz = _mm_set1_ps(centre.z), vr2 = _mm_set1_ps(r2);
        __m128 top = _mm_set1_ps(-1.0f);
        __m128i topIndex = _mm_set1_epi32(static_cast<int>(n)), index = _mm_setr_epi32(0, 1, 2, 3);
        const __m128i four = _mm_set1_epi32(4);
        for (; k + 4 <= n; k += 4) {
            const __m128 dx = _mm_sub_ps(_mm_loadu_ps(&mX[k]), cx);
            const __m128 dy = _mm_sub_ps(_mm_loadu_ps(&mY[k]), cy);
            const __m128 dz = _mm_sub_ps(_mm_loadu_ps(&mZ[k]), cz);
            const __m128 d2 =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            // minps(d2, nearest) = d2 < nearest ? d2 : nearest, std::min(nearest, d2) exactly.
            const __m128 nearest = _mm_min_ps(d2, _mm_loadu_ps(&mNearest[k]));
            _mm_storeu_ps(&mNearest[k], nearest);
            const __m128i lit = _mm_castps_si128(_mm_cmple_ps(d2, vr2));
            __m128i* litAt = reinterpret_cast<__m128i*>(&mLit[k]);
            _mm_storeu_si128(litAt, _mm_or_si128(_mm_loadu_si128(litAt), lit));
            if (score != Score::None) {
                const __m128 s = _mm_sqrt_ps(nearest);
                const __m128 w =
                    score == Score::WeightedSpread ? _mm_mul_ps(_mm_loadu_ps(&mWeight[k]), s) : s;
                const __m128 v = _mm_mul_ps(w, _mm_loadu_ps(&mJitter[k]));
                // Strictly greater: within a lane the earlier candidate keeps a tie.
                const __m128 greater = _mm_cmpgt_ps(v, top);
                top = _mm_or_ps(_mm_and_ps(greater, v), _mm_andnot_ps(greater, top));
                const __m128i g = _mm_castps_si128(greater);
                topIndex = _mm_or_si128(_mm_and_si128(g, index), _mm_andnot_si128(g, topIndex));
                index = _mm_add_epi32(index, four);
            }
        }
        if (score != Score::None) {
            // Lane by lane: the highest score, the lowest index among equal ones.
            alignas(16) float tops[4];
            alignas(16) std::int32_t indices[4];
            _mm_store_ps(tops, top);
            _mm_store_si128(reinterpret_cast<__m128i*>(indices), topIndex);
            for (int l = 0; l < 4; ++l)
                b.offerLane(tops[l], static_cast<std::size_t>(indices[l]));
        }
#endif
        for (; k < n; ++k) {
            const float dx = mX[k] - centre.x, dy = mY[k] - centre.y, dz = mZ[k] - centre.z;
            const float d2 = (dx * dx + dy * dy) + dz * dz;
            mNearest[k] = std::min(mNearest[k], d2);
            if (d2 <= r2) mLit[k] = ~0u;
            if (score != Score::None) b.offer(scoreOf(k, score), k);
        }
        return score == Score::None ? n : b.index(n);
    }

    /// Marks lit[index] for every candidate lit by a visit (a point is a candidate once).
    void markLit(std::vector<std::uint8_t>& lit) const {
        for (std::size_t k = 0; k < mCount; ++k)
            lit[mIndex[k]] = static_cast<std::uint8_t>(mLit[k] & 1u);
    }

private:
    /// The first of the highest scores offered in index order (strict '>' from -1).
    struct Best {
        float score = -1.0f;
        std::size_t at = std::numeric_limits<std::size_t>::max();
        void offer(float s, std::size_t k) {
            if (s > score) {
                score = s;
                at = k;
            }
        }
        /// A lane's best of candidates interleaved with the other lanes': a tie goes to the
        /// lower index.
        void offerLane(float s, std::size_t k) {
            if (s > score || (s == score && k < at)) {
                score = s;
                at = k;
            }
        }
        std::size_t index(std::size_t none) const { return score > -1.0f ? at : none; }
    };

    float scoreOf(std::size_t k, Score score) const {
        const float s = score == Score::None ? 1.0f : std::sqrt(mNearest[k]);
        return (score == Score::Spread ? s : mWeight[k] * s) * mJitter[k];
    }

    std::vector<float> mX, mY, mZ, mWeight, mJitter, mNearest;
    std::vector<std::uint32_t> mLit; ///< ~0u once within a centre's radius
    std::vector<std::uint32_t> mIndex;
    std::size_t mCount = 0;
};

/// A point's shadow from its voxel's fixed-point value, as ShadowGrid::shadow() makes it.
float shadowOf(std::int32_t raw) {
    return static_cast<float>(raw / ShadowGrid::kScale - kShadowA);
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
        // A histogram no larger than a few times the points (the oak's ~5,000 span ~500).
        if (bottom < 0 || units > 4 * raw.size() + 4096) return;
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
    const std::size_t n = points.size();
    std::vector<std::int32_t> raw(n);
    std::vector<float> shadow(n);
    for (std::size_t i = 0; i < n; ++i) {
        raw[i] = grid.raw(sources[i].voxel);
        shadow[i] = shadowOf(raw[i]);
    }
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
    std::vector<std::uint8_t> lit;
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
        Candidates outer(n), inner(n);
        for (std::size_t i = 0; i < n; ++i) {
            const bool isOuter = shadow[i] <= median[band[i]];
            const float exposure = 1.0f / (1.0f + std::max(shadow[i], 0.0f));
            outer.offer(isOuter, points[i], std::sqrt(exposure), jitter[i], i);
            inner.offer(!isOuter && shadow[i] < shedAbove, points[i], 1.0f, jitter[i], i);
        }
        const std::size_t k = std::min(n, static_cast<std::size_t>(params.clusters));
        // Each centre's visit scores the candidates for the next one.
        std::size_t best = outer.best(Score::None);
        for (std::size_t c = 0; c < k; ++c) {
            const glm::vec3 centre = best < outer.size() ? outer.point(best) : points[0];
            const float r = params.clusterRadius * halfExtent *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f));
            best = outer.visit(centre, r * r, c + 1 < k ? Score::WeightedSpread : Score::None);
            inner.visit(centre, r * r, Score::None);
        }
        // Inner clusters: among the shaded inside that is not shed, as far from every centre
        // as possible, so the limbs carry foliage through the depth of the crown.
        const float innerR = params.innerRadius * params.clusterRadius * halfExtent;
        best = innerCount > 0 ? inner.best(Score::Spread) : inner.size();
        for (int c = 0; c < innerCount && best < inner.size(); ++c) {
            const glm::vec3 centre = inner.point(best);
            const float r =
                innerR * (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f));
            outer.visit(centre, r * r, Score::None);
            best = inner.visit(centre, r * r, c + 1 < innerCount ? Score::Spread : Score::None);
        }
        lit.assign(n, 0);
        outer.markLit(lit);
        inner.markLit(lit);
    }

    // Every point written, the kept ones counted (a branch here would be mispredicted often).
    std::vector<glm::vec3> kept(n + 1);
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        kept[m] = points[i];
        m += shadow[i] < shedAbove && (lit.empty() || lit[i] != 0) ? 1 : 0;
    }
    kept.resize(m);
    return kept;
}

} // namespace sylva::growth
