// Stochastic rules and rand(): frequencies within a statistical tolerance, determinism by seed.
#include <gtest/gtest.h>

#include <cmath>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

TEST(Stochastic, FrequenciesMatchTheWeightsOverManySeeds) {
    const Grammar g = parseGrammar("axiom: A\nA -> B : 0.2\nA -> C : 0.3\nA -> D : 0.5\n");
    const int n = 20000;
    int counts[3] = {};
    for (int seed = 0; seed < n; ++seed) {
        const std::string s = formatModules(derive(g, options(1, seed)));
        ASSERT_EQ(s.size(), 1u);
        counts[s[0] - 'B']++;
    }
    const double p[3] = {0.2, 0.3, 0.5};
    for (int k = 0; k < 3; ++k) {
        const double sigma = std::sqrt(p[k] * (1 - p[k]) / n);
        EXPECT_NEAR(static_cast<double>(counts[k]) / n, p[k], 5 * sigma) << k;
    }
}

TEST(Stochastic, FrequenciesWithinOneLongWord) {
    // 2^14 A's drawn in one generation.
    Grammar draw = parseGrammar("axiom: A\nA -> B : 0.25\nA -> C : 0.75\n");
    draw.axiom.modules.assign(1u << 14, ModuleCall{'A', 0, 0});
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const std::string s = formatModules(derive(draw, options(1, seed)));
        const double n = static_cast<double>(s.size());
        const double sigma = std::sqrt(0.25 * 0.75 / n);
        EXPECT_NEAR(countOf(s, 'B') / n, 0.25, 5 * sigma);
        EXPECT_EQ(countOf(s, 'B') + countOf(s, 'C'), s.size());
    }
}

TEST(Stochastic, SameSeedSameWordDifferentSeedDifferentWord) {
    const std::string text = "axiom: F\nF -> F[+F]F : 0.34\nF -> F[-F]F : 0.33\nF -> FF : 0.33\n";
    const std::string a = expand(text, 6, 7);
    EXPECT_EQ(a, expand(text, 6, 7));
    EXPECT_NE(a, expand(text, 6, 8));
    // The grammar's seed: is the default.
    EXPECT_EQ(expand("seed: 7\n" + text, 6), a);
}

TEST(Stochastic, EarlierGenerationsDoNotDependOnTheGenerationCount) {
    // Each generation draws from its own stream, so n+1 generations continue the n-generation
    // word: deriving one more generation of the n-word's modules reproduces the n+1 word.
    const std::string text = "axiom: X\nX -> XY : 0.5\nX -> YX : 0.5\nY -> Y\n";
    const std::string w5 = expand(text, 5, 3);
    const std::string w6 = expand(text, 6, 3);
    // Y is never rewritten and every X produces exactly one X: the Y count grows by 1.
    EXPECT_EQ(countOf(w5, 'Y') + 1, countOf(w6, 'Y'));
    EXPECT_EQ(countOf(w6, 'X'), 1u);
}

TEST(Stochastic, GroupsAreKeyedByContextAndCondition) {
    // Two groups for A: x > 1 (stochastic between B and C) and x <= 1 (deterministic D).
    const std::string text = "axiom: A(2)A(0)\n"
                             "A(x) : x > 1 -> B : 0.5\n"
                             "A(x) : x > 1 -> C : 0.5\n"
                             "A(x) : x <= 1 -> D\n";
    int b = 0;
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        const std::string s = expand(text, 1, seed);
        ASSERT_EQ(s.size(), 2u);
        ASSERT_TRUE(s[0] == 'B' || s[0] == 'C') << s;
        ASSERT_EQ(s[1], 'D');
        b += s[0] == 'B';
    }
    EXPECT_GT(b, 60);
    EXPECT_LT(b, 140);
}

TEST(Stochastic, RandInExpressionsIsSeeded) {
    const std::string text = "axiom: A(0)\nA(x) -> A(rand(10, 20))B(rand(-1, 1))\n";
    const std::string a = expand(text, 3, 11);
    EXPECT_EQ(a, expand(text, 3, 11));
    EXPECT_NE(a, expand(text, 3, 12));
    const ModuleString s = derive(parseGrammar(text), options(1, 5));
    ASSERT_EQ(s.params.size(), 2u);
    EXPECT_GE(s.params[0], 10.0);
    EXPECT_LT(s.params[0], 20.0);
    EXPECT_GE(s.params[1], -1.0);
    EXPECT_LT(s.params[1], 1.0);
}
