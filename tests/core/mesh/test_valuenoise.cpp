#include <gtest/gtest.h>

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
