// Lit attraction points (issue #33): sunlit clusters and shedding of the shaded inside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "engine/growth/envelope.h"
#include "engine/growth/litattractors.h"
#include "engine/growth/litcandidates.h"
#include "engine/growth/shadowgrid.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

using namespace sylva;
using namespace sylva::growth;

namespace {
std::vector<glm::vec3> crown() {
    return Envelope::ellipsoid(glm::vec3(0, 6, 0), glm::vec3(4, 3, 4)).sample(4000, 5);
}
} // namespace

TEST(LitAttractors, WithoutLightEveryPointIsKept) {
    const std::vector<glm::vec3> pts = crown();
    EXPECT_EQ(litAttractors(pts, LightParams{}, 1), pts);
}

TEST(LitAttractors, ShedsTheMostShadedFractionFromBelow) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.shadedFraction = 0.3f;
    const std::vector<glm::vec3> kept = litAttractors(pts, p, 1);
    EXPECT_LE(kept.size(), pts.size() * 71 / 100);
    EXPECT_GE(kept.size(), pts.size() * 55 / 100); // ties at the quantile are few
    // The highest point is lit; the shed ones are lower on average (shadow falls downward).
    const auto higher = [](const glm::vec3& a, const glm::vec3& b) { return a.y < b.y; };
    EXPECT_EQ(*std::max_element(kept.begin(), kept.end(), higher),
              *std::max_element(pts.begin(), pts.end(), higher));
    double keptY = 0.0, allY = 0.0;
    for (const glm::vec3& q : kept)
        keptY += q.y / kept.size();
    for (const glm::vec3& q : pts)
        allY += q.y / pts.size();
    EXPECT_GT(keptY, allY + 0.2);
}

TEST(LitAttractors, ClustersLeaveGapsAndAreDeterministic) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.clusters = 12;
    p.clusterRadius = 0.3f;
    const std::vector<glm::vec3> a = litAttractors(pts, p, 1), b = litAttractors(pts, p, 1),
                                 c = litAttractors(pts, p, 2);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    EXPECT_GT(a.size(), pts.size() / 10);
    EXPECT_LT(a.size(), pts.size() * 8 / 10); // gaps between the clusters
    // Kept points keep their input order (a subsequence).
    std::size_t j = 0;
    for (const glm::vec3& q : pts)
        if (j < a.size() && q == a[j]) ++j;
    EXPECT_EQ(j, a.size());
    // No cluster sits in the shaded lower inside: the lowest central points are gone.
    for (const glm::vec3& q : a)
        EXPECT_FALSE(q.y < 4.0f && q.x * q.x + q.z * q.z < 0.25f)
            << q.x << " " << q.y << " " << q.z;
}

TEST(LitAttractors, BadParametersSayTheRange) {
    LightParams p;
    p.clusters = -1;
    EXPECT_THROW(validate(p), InvalidInput);
    p = {};
    p.shadedFraction = 1.0f;
    try {
        validate(p);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("shaded_fraction"), std::string::npos);
    }
    p = {};
    p.clusterRadius = 0.0f;
    EXPECT_THROW(validate(p), InvalidInput);
}

// Lit clusters alone are a shell; inner clusters put points back in its depth (foliage on the
// main limbs) without touching the shed most-shaded points.
TEST(LitAttractors, InnerClustersFillTheDepthOfTheShell) {
    const std::vector<glm::vec3> pts = crown();
    LightParams p;
    p.clusters = 12;
    p.clusterRadius = 0.3f;
    p.shadedFraction = 0.1f;
    const auto deep = [](const std::vector<glm::vec3>& v) {
        std::size_t n = 0;
        for (const glm::vec3& q : v) {
            const glm::vec3 d = (q - glm::vec3(0, 6, 0)) / glm::vec3(4, 3, 4);
            if (glm::dot(d, d) < 0.6f * 0.6f) ++n;
        }
        return n;
    };
    const std::vector<glm::vec3> shell = litAttractors(pts, p, 1);
    p.innerClusters = 8;
    const std::vector<glm::vec3> filled = litAttractors(pts, p, 1);
    EXPECT_GT(deep(filled), 2 * deep(shell) + 40) << deep(shell) << " " << deep(filled);
    EXPECT_GT(filled.size(), shell.size());
    // Every lit point is still there: the inner clusters only add.
    std::size_t j = 0;
    for (const glm::vec3& q : filled)
        if (j < shell.size() && q == shell[j]) ++j;
    EXPECT_EQ(j, shell.size());
    // Without lit clusters there is no shell to fill: inner clusters do nothing.
    LightParams only;
    only.innerClusters = 8;
    EXPECT_EQ(litAttractors(pts, only, 1), pts);
    only.innerRadius = 0.0f;
    EXPECT_THROW(validate(only), InvalidInput);
}

namespace {

// The straightforward version the engine's litAttractors replaced (issue 41, fifth pass): the
// shadows read back as floats, std::nth_element for the quantile and the band medians, every
// centre chosen by a full scoring pass, every point tested against every centre. The engine's
// version (one visit a centre on SSE2, counted order statistics, branch-free compaction) must
// give the same points, bit for bit.
std::vector<glm::vec3> straightforwardLitAttractors(const std::vector<glm::vec3>& points,
                                                    const LightParams& params, std::uint64_t seed) {
    if (points.empty() || (params.clusters == 0 && params.shadedFraction <= 0.0f)) return points;
    const int innerCount = params.clusters > 0 ? params.innerClusters : 0;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float halfExtent = std::max((hi.x - lo.x + hi.y - lo.y + hi.z - lo.z) / 6.0f, 1e-3f);
    const ShadowKernel kernel = ShadowKernel::make(1.0, 2.0, 4);
    ShadowGrid grid(params.voxelSize, lo.y - params.voxelSize, 4);
    for (const glm::vec3& p : points)
        grid.addPyramid(grid.voxelOf(p), kernel);
    std::vector<float> shadow(points.size()), exposure(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        shadow[i] = static_cast<float>(grid.shadow(grid.voxelOf(points[i])) - 1.0);
        exposure[i] = 1.0f / (1.0f + std::max(shadow[i], 0.0f));
    }
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
        std::vector<std::size_t> outer, inner;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (shadow[i] <= median[bandOf(points[i])])
                outer.push_back(i);
            else if (shadow[i] < shedAbove)
                inner.push_back(i);
        }
        std::vector<float> nearest(points.size(), std::numeric_limits<float>::max());
        auto closer = [&](const glm::vec3& centre) {
            for (std::size_t i = 0; i < points.size(); ++i) {
                const glm::vec3 d = points[i] - centre;
                nearest[i] = std::min(nearest[i], glm::dot(d, d));
            }
        };
        auto best = [&](const std::vector<std::size_t>& among, bool spread, bool weighted) {
            std::size_t found = among.size();
            float top = -1.0f;
            for (std::size_t k = 0; k < among.size(); ++k) {
                const std::size_t i = among[k];
                const float s = spread ? std::sqrt(nearest[i]) : 1.0f;
                const float score = (weighted ? std::sqrt(exposure[i]) * s : s) * jitter[i];
                if (score > top) {
                    top = score;
                    found = k;
                }
            }
            return found;
        };
        const std::size_t k = std::min(points.size(), static_cast<std::size_t>(params.clusters));
        for (std::size_t c = 0; c < k; ++c) {
            const std::size_t b = best(outer, !centres.empty(), true);
            const glm::vec3 centre = b < outer.size() ? points[outer[b]] : points[0];
            centres.push_back(centre);
            radii.push_back(params.clusterRadius * halfExtent *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            closer(centre);
        }
        const float innerR = params.innerRadius * params.clusterRadius * halfExtent;
        for (int c = 0; c < innerCount; ++c) {
            const std::size_t b = best(inner, true, false);
            if (b == inner.size()) break;
            const glm::vec3 centre = points[inner[b]];
            centres.push_back(centre);
            radii.push_back(innerR *
                            (1.0f + params.clusterSpread * (rng.uniformf(0.0f, 1.0f) - 0.5f)));
            closer(centre);
        }
    }
    std::vector<glm::vec3> kept;
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

} // namespace

// Point counts that are not multiples of four (the SSE2 lanes' tails), a crown whose shadows
// span few fixed-point steps (counted) and a dense one whose shadows span many (nth_element),
// shedding alone, clusters alone, clusters with inner clusters: the same points as the
// straightforward version.
TEST(LitAttractors, SameAsTheStraightforwardVersion) {
    const Envelope wide = Envelope::ellipsoid(glm::vec3(0, 5.8f, 0), glm::vec3(7.5f, 4.6f, 7.5f));
    const Envelope dense = Envelope::sphere(glm::vec3(0, 3, 0), 0.9f);
    struct Case {
        const Envelope* envelope;
        std::size_t count;
        int clusters, inner;
        float shaded;
    };
    const Case cases[] = {{&wide, 5000, 40, 0, 0.25f}, {&wide, 3001, 24, 18, 0.08f},
                          {&wide, 1999, 30, 16, 0.0f}, {&wide, 4003, 0, 0, 0.3f},
                          {&wide, 7, 12, 3, 0.2f},     {&dense, 20001, 20, 20, 0.12f},
                          {&dense, 6002, 0, 0, 0.5f},  {&wide, 2, 5, 5, 0.5f}};
    int compared = 0;
    for (const Case& c : cases)
        for (std::uint64_t seed : {1u, 11u, 1003u}) {
            const std::vector<glm::vec3> pts = c.envelope->sample(c.count, seed);
            LightParams p;
            p.clusters = c.clusters;
            p.innerClusters = c.inner;
            p.shadedFraction = c.shaded;
            p.clusterRadius = 0.38f;
            const std::vector<glm::vec3> fast = litAttractors(pts, p, seed);
            const std::vector<glm::vec3> plain = straightforwardLitAttractors(pts, p, seed);
            ASSERT_EQ(fast.size(), plain.size()) << c.count << " points, seed " << seed;
            // Bit for bit (memcmp: never with the null data() of an empty vector).
            EXPECT_TRUE(fast.empty() || std::memcmp(fast.data(), plain.data(),
                                                    fast.size() * sizeof(glm::vec3)) == 0)
                << c.count << " points, seed " << seed;
            if (c.count > 100) {
                EXPECT_LT(fast.size(), pts.size()) << "nothing dropped: a weak case";
            }
            ++compared;
        }
    EXPECT_EQ(compared, 24);
}

// The candidates' visits on every lane count this processor has (scalar, SSE2, AVX, AVX-512)
// give the same distances, lit flags and best candidates, for every kind of visit and counts
// that leave tails of every length.
TEST(LitAttractors, CandidateVisitsAgreeOnEveryLaneCount) {
    std::vector<CandidateLanes> lanes = {CandidateLanes::Scalar, CandidateLanes::Sse2};
    if (LitCandidates::hasAvx()) lanes.push_back(CandidateLanes::Avx);
    if (LitCandidates::hasAvx512()) lanes.push_back(CandidateLanes::Avx512);
    const CandidateVisit kinds[] = {CandidateVisit::WeightedSpread, CandidateVisit::Nearest,
                                    CandidateVisit::Spread, CandidateVisit::Lit,
                                    CandidateVisit::WeightedSpread};
    for (std::size_t count : {1u, 7u, 8u, 13u, 16u, 33u, 500u, 1003u}) {
        const std::vector<glm::vec3> pts = Envelope::sphere(glm::vec3(0, 4, 0), 3.0f)
                                               .sample(std::max<std::size_t>(count, 19), count);
        Rng rng(count);
        std::vector<LitCandidates> sets;
        for (std::size_t l = 0; l < lanes.size(); ++l)
            sets.emplace_back(count);
        for (std::size_t i = 0; i < count; ++i) {
            // Equal scores on purpose (the same point, weight and jitter again further on,
            // in the same lane or another): ties go to the lower index on every lane count.
            const std::size_t twin = i % 19;
            const float w = static_cast<float>(twin % 4) / 4.0f + 0.25f;
            const float j = twin % 3 == 0 ? 1.0f : 0.8f;
            for (LitCandidates& s : sets)
                s.offer(i % 5 != 0, pts[twin], w, j, i);
        }
        std::vector<std::size_t> firsts;
        for (const LitCandidates& s : sets)
            firsts.push_back(s.best(CandidateScore::Weight));
        for (std::size_t l = 1; l < sets.size(); ++l)
            EXPECT_EQ(firsts[l], firsts[0]);
        for (int v = 0; v < 12; ++v) {
            const CandidateVisit what = kinds[v % 5];
            const glm::vec3 centre = pts[rng.below(pts.size())] + glm::vec3(0.01f * v);
            const float r2 = rng.uniformf(0.1f, 2.0f);
            std::vector<std::size_t> best;
            for (std::size_t l = 0; l < sets.size(); ++l)
                best.push_back(sets[l].visit(centre, r2, what, lanes[l]));
            for (std::size_t l = 1; l < sets.size(); ++l) {
                EXPECT_EQ(best[l], best[0]) << count << " candidates, visit " << v;
                for (std::size_t k = 0; k < sets[0].size(); ++k) {
                    ASSERT_EQ(sets[l].nearest(k), sets[0].nearest(k)) << k;
                    ASSERT_EQ(sets[l].lit(k), sets[0].lit(k)) << k;
                }
            }
            if (sets[0].size() > 0 &&
                (what == CandidateVisit::Spread || what == CandidateVisit::WeightedSpread)) {
                EXPECT_LT(best[0], sets[0].size());
            }
        }
        std::vector<std::uint8_t> lit(count, 0);
        sets[0].markLit(lit);
        std::size_t marked = 0;
        for (std::size_t i = 0; i < count; ++i)
            marked += lit[i];
        std::size_t litCount = 0;
        for (std::size_t k = 0; k < sets[0].size(); ++k)
            litCount += sets[0].lit(k) ? 1 : 0;
        EXPECT_EQ(marked, litCount);
    }
}
