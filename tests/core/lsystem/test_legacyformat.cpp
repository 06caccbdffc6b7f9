// The legacy plain format of reference 000: generations, angle in radians, thickness, axiom,
// then `Rule = Replacement : Probability`.
#include <gtest/gtest.h>

#include <numbers>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

TEST(LegacyFormat, HeaderAndDeterministicRule) {
    const Grammar g = parseGrammar("4\n"
                                   "0.39269908169872414\n"
                                   "0.2\n"
                                   "\n"
                                   "F\n"
                                   "\n"
                                   "F = F[+F]F[-F]F : 1.0\n",
                                   "old.txt");
    EXPECT_TRUE(g.legacyFormat);
    EXPECT_EQ(g.generations, 4);
    EXPECT_NEAR(g.angleDegrees, 22.5, 1e-12);
    EXPECT_DOUBLE_EQ(g.width, 0.2);
    const std::string s = formatModules(derive(g));
    EXPECT_EQ(countOf(s, 'F'), 625u);
    EXPECT_EQ(formatModules(derive(g, options(1))), "F[+F]F[-F]F");
}

TEST(LegacyFormat, StochasticRulesAndOptionalProbability) {
    const std::string text = "3\n" + std::to_string(std::numbers::pi / 2) +
                             "\n0.1\nX\nX = F[+X]F[-X]X : 0.5\nX = F[-X]FX : 0.5\nF = FF\n";
    const Grammar g = parseGrammar(text);
    EXPECT_TRUE(g.stochastic);
    EXPECT_NEAR(g.angleDegrees, 90.0, 1e-4);
    const std::string a = expand(text, {}, 1);
    EXPECT_EQ(a, expand(text, {}, 1));
    bool differs = false;
    for (std::uint64_t seed = 2; seed < 10 && !differs; ++seed)
        differs = expand(text, {}, seed) != a;
    EXPECT_TRUE(differs);
}

TEST(LegacyFormat, Diagnostics) {
    auto one = [](const std::string& text) {
        const auto d = diagnose(text);
        EXPECT_EQ(d.size(), 1u) << text;
        return d.empty() ? Diagnostic{} : d[0];
    };
    Diagnostic d = one("2\n0.5\n0.1\nF\nF = F[F : 1\n");
    EXPECT_EQ(d.line, 5);
    EXPECT_EQ(d.column, 6);
    d = one("2\n0.5\n0.1\nF\nF = FF : 0.5\nF = F : 0.4\n");
    EXPECT_EQ(d.line, 5);
    EXPECT_NE(d.message.find("sum to 0.9"), std::string::npos) << d.message;
    d = one("2\n0.5\n0.1\nF\nF -> FF\n");
    EXPECT_EQ(d.line, 5);
    EXPECT_NE(d.message.find("Rule = Replacement"), std::string::npos) << d.message;
    d = one("2\n0.5\n");
    EXPECT_EQ(d.line, 0);
    EXPECT_NE(d.message.find("no axiom"), std::string::npos) << d.message;
    d = one("2\nabc\n0.1\nF\n");
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 1);
}

TEST(LegacyFormat, DetectionNeedsABareIntegerFirst) {
    EXPECT_FALSE(parseGrammar("# comment\naxiom: F\n").legacyFormat);
    EXPECT_TRUE(parseGrammar("# comment\n\n 3 \n0.1\n0.1\nF\n").legacyFormat);
}
