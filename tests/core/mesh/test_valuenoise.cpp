#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "engine/mesh/valuenoise.h"
#include "engine/util/random.h"

using namespace sylva;

// The grid of lattice values (cover) changes nothing: points inside the box, outside it and
// on its edges, visited in runs (as a crown's cards are) and at random, give the values of a
// noise without the grid, bit for bit; a box larger than allowed keeps no grid and the same
// values.
TEST(ValueNoise, GridKeepsTheSameValues) {
    for (std::size_t maxPoints : {std::size_t{100000}, std::size_t{10}}) {
        mesh::ValueNoise plain(99), covered(99);
        covered.cover({-3.2, 0.5, -7.9}, {4.1, 9.7, -0.2}, maxPoints);
        Rng rng(3);
        glm::dvec3 p(0.0, 2.0, -3.0);
        for (int i = 0; i < 20000; ++i) {
            if (i % 7 == 0)
                p = glm::dvec3(rng.uniform(-6, 7), rng.uniform(-2, 12), rng.uniform(-10, 2));
            else
                p += glm::dvec3(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3),
                                rng.uniform(-0.3, 0.3));
            const glm::dvec3 a = plain(p), b = covered(p);
            EXPECT_EQ(a, b) << i;
            EXPECT_LE(glm::abs(a.x), 1.0);
        }
        EXPECT_EQ(plain.lattice(-4, 11, 2), covered.lattice(-4, 11, 2));
    }
}

namespace {

double smoothStep(double t) {
    return t * t * (3.0 - 2.0 * t);
}

// The noise as written first: std::floor, the eight lattice values, the same interpolations.
glm::dvec3 straightforwardNoise(const mesh::ValueNoise& noise, const glm::dvec3& p) {
    const glm::dvec3 f(std::floor(p.x), std::floor(p.y), std::floor(p.z));
    const glm::dvec3 t = p - f;
    const auto ix = static_cast<std::int64_t>(f.x), iy = static_cast<std::int64_t>(f.y),
               iz = static_cast<std::int64_t>(f.z);
    const double sx = smoothStep(t.x), sy = smoothStep(t.y), sz = smoothStep(t.z);
    glm::dvec3 c[2][2];
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy) {
            const glm::dvec3 a = noise.lattice(ix, iy + dy, iz + dz);
            const glm::dvec3 b = noise.lattice(ix + 1, iy + dy, iz + dz);
            c[dz][dy] = a + (b - a) * sx;
        }
    const glm::dvec3 y0 = c[0][0] + (c[0][1] - c[0][0]) * sy;
    const glm::dvec3 y1 = c[1][0] + (c[1][1] - c[1][0]) * sy;
    return y0 + (y1 - y0) * sz;
}

bool sameBits(const glm::dvec3& a, const glm::dvec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

// The noise's own floors (no branch on the sign) against std::floor's noise bit for bit: integers
// and -0 on every axis, a hair either side of them, halves, points either side of zero, and
// large coordinates up to and past 2^52 (where the floors are the plain ones); with a grid and
// without. A floor one off (the truncation less 1 where it is below x) fails. (The floor of -0
// is kept -0, but the noise cannot show it: t is then -0 or +0, and both smooth to +0.)
TEST(ValueNoise, FloorsAreStdFloor) {
    std::vector<double> coordinates = {0.0,          -0.0,          1.0,      -1.0,    0.5,
                                       -0.5,         2.75,          -2.75,    1e-300,  -1e-300,
                                       0x1p52 - 1.0, -0x1p52 + 1.0, 0x1p52,   -0x1p52, 0x1p60,
                                       -0x1p60,      123456.5,      -123456.5};
    for (double x : {1.0, -1.0, 3.0, -3.0, 0.0}) {
        coordinates.push_back(std::nextafter(x, 10.0));
        coordinates.push_back(std::nextafter(x, -10.0));
    }
    Rng rng(8);
    for (int i = 0; i < 200; ++i)
        coordinates.push_back(rng.uniform(-50.0, 50.0));
    for (bool covered : {false, true}) {
        mesh::ValueNoise noise(41);
        if (covered) noise.cover({-60.0, -60.0, -60.0}, {60.0, 60.0, 60.0}, 2'000'000);
        for (std::size_t i = 0; i < coordinates.size(); ++i)
            for (std::size_t j = 0; j < coordinates.size(); j += 7)
                for (std::size_t k = 0; k < coordinates.size(); k += 11) {
                    const glm::dvec3 p(coordinates[i], coordinates[j], coordinates[k]);
                    EXPECT_TRUE(sameBits(noise(p), straightforwardNoise(noise, p)))
                        << p.x << " " << p.y << " " << p.z << " " << covered;
                }
    }
}
