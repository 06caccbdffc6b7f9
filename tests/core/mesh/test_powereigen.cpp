#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "engine/mesh/powereigen.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

// The covariance of \p count points spread \p spread along x, y and z, turned by a random
// rotation: the leaf cards' kind of matrix.
glm::dmat3 covariance(Rng& rng, const glm::dvec3& spread, int count) {
    const glm::dvec3 a = glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0));
    const glm::dvec3 b = glm::normalize(glm::cross(a, glm::dvec3(0.3, 1.0, -0.2)));
    const glm::dvec3 c = glm::cross(a, b);
    std::vector<glm::dvec3> pts;
    glm::dvec3 mean(0.0);
    for (int i = 0; i < count; ++i) {
        pts.push_back(a * (spread.x * rng.uniform(-1, 1)) + b * (spread.y * rng.uniform(-1, 1)) +
                      c * (spread.z * rng.uniform(-1, 1)) + glm::dvec3(3.0, 7.0, -2.0));
        mean += pts.back();
    }
    mean /= static_cast<double>(count);
    glm::dmat3 cov(0.0);
    for (const glm::dvec3& p : pts)
        cov += glm::outerProduct(p - mean, p - mean);
    return cov;
}

// Both versions on the same matrices and starts, in batches of every size up to kPowerLanes.
void expectSameDirections(const std::vector<glm::dmat3>& cs, const std::vector<glm::dvec3>& starts,
                          double tolerance) {
    for (std::size_t batch = 1; batch <= mesh::kPowerLanes; ++batch)
        for (std::size_t first = 0; first + batch <= cs.size(); first += batch) {
            std::vector<glm::dvec3> fast(starts.begin() + first, starts.begin() + first + batch);
            std::vector<glm::dvec3> plain = fast;
            mesh::largestEigenvectors(&cs[first], fast.data(), batch);
            mesh::largestEigenvectorsStepwise(&cs[first], plain.data(), batch);
            for (std::size_t k = 0; k < batch; ++k) {
                EXPECT_NEAR(glm::length(fast[k]), 1.0, 1e-12) << first + k;
                EXPECT_LT(glm::length(fast[k] - plain[k]), tolerance) << first + k;
            }
        }
}

} // namespace

// The batched power iteration (the fourth power by squarings, powers of two between blocks,
// eight lanes on SSE2) gives the straightforward one's directions, also where the two largest
// spreads are nearly equal and 24 steps have not converged.
TEST(PowerEigen, BatchedIterationMatchesStepwise) {
    Rng rng(41);
    std::vector<glm::dmat3> cs;
    std::vector<glm::dvec3> starts;
    for (int i = 0; i < 200; ++i) {
        const double near = i % 3 == 0 ? 1.0 + 1e-3 * rng.uniform() : rng.uniform(0.2, 3.0);
        cs.push_back(covariance(rng, {near, 1.0, rng.uniform(0.0, 0.5)}, 4 + i % 29));
        starts.push_back(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    }
    expectSameDirections(cs, starts, 1e-9);
}

// A matrix whose products vanish keeps its vector, as does a lane of the batch beside it; a
// line of points (rank one) gives the line.
TEST(PowerEigen, VanishingAndRankOneMatrices) {
    Rng rng(7);
    std::vector<glm::dmat3> cs;
    std::vector<glm::dvec3> starts;
    for (int i = 0; i < 16; ++i) {
        cs.push_back(i % 2 == 0 ? glm::dmat3(0.0) : covariance(rng, {2.0, 0.0, 0.0}, 5));
        starts.push_back(glm::normalize(glm::dvec3(0.2, 0.9, 0.1 * i)));
    }
    expectSameDirections(cs, starts, 1e-9);
    std::vector<glm::dvec3> v = starts;
    mesh::largestEigenvectors(cs.data(), v.data(), mesh::kPowerLanes);
    for (std::size_t k = 0; k < mesh::kPowerLanes; k += 2)
        EXPECT_EQ(v[k], starts[k]);
    for (std::size_t k = 1; k < mesh::kPowerLanes; k += 2) {
        // An eigenvector: its product is along it.
        const glm::dvec3 product = cs[k] * v[k];
        EXPECT_GT(glm::length(product), 0.0);
        EXPECT_LT(glm::length(glm::cross(product, v[k])), 1e-9 * glm::length(product)) << k;
    }
}

// largestEigenvectors (one AVX-512 register a lane where there is AVX-512) gives the SSE2 pairs'
// vectors bit for bit, in batches of every size: spreads near equal, tiny and huge matrices,
// zero matrices, and rank-one ones started across their line (whose products vanish).
TEST(PowerEigen, LanesMatchThePairsBitForBit) {
    Rng rng(43);
    std::vector<glm::dmat3> cs;
    std::vector<glm::dvec3> starts;
    for (int i = 0; i < 120; ++i) {
        const double near = i % 3 == 0 ? 1.0 + 1e-3 * rng.uniform() : rng.uniform(0.2, 3.0);
        glm::dmat3 c = covariance(rng, {near, 1.0, rng.uniform(0.0, 0.5)}, 2 + i % 23);
        glm::dvec3 start(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        if (i % 7 == 3) c = glm::dmat3(0.0);
        if (i % 11 == 5) c *= 1e-150;
        if (i % 13 == 6) c *= 1e150;
        if (i % 17 == 8) {
            c = glm::outerProduct(glm::dvec3(1.0, 2.0, 0.5), glm::dvec3(1.0, 2.0, 0.5));
            start = glm::dvec3(2.0, -1.0, 0.0); // across the line: its product is zero
        }
        cs.push_back(c);
        starts.push_back(start);
    }
    for (std::size_t batch = 1; batch <= mesh::kPowerLanes; ++batch)
        for (std::size_t first = 0; first + batch <= cs.size(); first += batch) {
            std::vector<glm::dvec3> lanes(starts.begin() + first, starts.begin() + first + batch);
            std::vector<glm::dvec3> pairs = lanes;
            mesh::largestEigenvectors(&cs[first], lanes.data(), batch);
            mesh::largestEigenvectorsPairs(&cs[first], pairs.data(), batch);
            for (std::size_t k = 0; k < batch; ++k)
                for (int e = 0; e < 3; ++e)
                    EXPECT_EQ(std::bit_cast<std::uint64_t>(lanes[k][e]),
                              std::bit_cast<std::uint64_t>(pairs[k][e]))
                        << first + k << " " << e;
        }
}
