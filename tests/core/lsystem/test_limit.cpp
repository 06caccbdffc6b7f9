// The symbol limit: predicted before the memory is spent, naming the generation.
#include <gtest/gtest.h>

#include <cmath>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

namespace {

std::string limitMessage(const Grammar& g, int generations, std::size_t limit) {
    try {
        derive(g, options(generations, std::nullopt, limit));
    } catch (const LimitExceeded& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Limit, FastPathPredictsTheExactLength) {
    const Grammar g = parseGrammar("axiom: F\nF -> FF\n");
    EXPECT_EQ(derive(g, options(9, std::nullopt, 512)).size(), 512u);
    EXPECT_EQ(limitMessage(g, 10, 512), "generation 10 would hold 1024 modules, more than the "
                                        "symbol limit of 512; derive fewer generations or raise "
                                        "the limit (the lsystem node's symbol_limit, sylva-cli "
                                        "expand --limit; at most 2000000000)");
    // A thousand generations stop at generation 10 without overflowing the counts.
    EXPECT_NE(limitMessage(g, 1000, 1000).find("generation 10 "), std::string::npos);
    // The default limit is 20 million: 2^25 > 2e7 fails at generation 25.
    const ModuleString ok = derive(g, options(24));
    EXPECT_EQ(ok.size(), 1u << 24);
    EXPECT_THROW(derive(g, options(25)), LimitExceeded);
}

TEST(Limit, GeneralPathNeverHoldsMoreThanTheLimit) {
    // Parametric: 2^n modules at generation n.
    const Grammar g = parseGrammar("axiom: A(0)\nA(x) -> A(x+1)A(x+1)\n");
    EXPECT_EQ(derive(g, options(6, std::nullopt, 64)).size(), 64u);
    const std::string m = limitMessage(g, 7, 64);
    EXPECT_NE(m.find("generation 7 would hold more than 64 modules"), std::string::npos) << m;
    // Stochastic: the exact length is only known by drawing; it throws iff it exceeds.
    const Grammar s = parseGrammar("axiom: A\nA -> AA : 0.5\nA -> A : 0.5\n");
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const std::size_t full = derive(s, options(8, seed, 1u << 20)).size();
        EXPECT_NO_THROW(derive(s, options(8, seed, full)));
        EXPECT_THROW(derive(s, options(8, seed, full - 1)), LimitExceeded);
    }
}

TEST(Limit, TheAxiomCountsAsGenerationZero) {
    const Grammar g = parseGrammar("axiom: FFFF\n");
    EXPECT_NE(limitMessage(g, 0, 3).find("generation 0 would hold 4 modules"), std::string::npos);
}

// The parameter limit, twice the symbol limit: without it 20 million modules of 8 parameters
// took 3.4 GB before the symbol limit stopped them.
TEST(Limit, ModuleParametersAreLimitedToo) {
    const Grammar g =
        parseGrammar("axiom: A(1,2,3,4,5)\nA(a,b,c,d,e) -> A(a,b,c,d,e)A(a,b,c,d,e)\n");
    EXPECT_EQ(paramLimitOf(100), 200u);
    EXPECT_EQ(derive(g, options(5, std::nullopt, 100)).params.size(), 160u); // 32 modules
    EXPECT_EQ(limitMessage(g, 6, 100),
              "generation 6 would hold more than 200 module parameters, twice the symbol limit of "
              "100; derive fewer generations or raise the limit (the lsystem node's symbol_limit, "
              "sylva-cli expand --limit; at most 2000000000)");
    EXPECT_EQ(derive(g, options(6, std::nullopt, 160)).size(), 64u); // 320 parameters fit
}

// The time limit: within the symbol limit a grammar can rewrite 20 million modules for 1000
// generations (hours). These grammars would take seconds to minutes; with a limit of a
// millisecond (or a microsecond) they stop with LimitExceeded naming the limit and how to
// raise it, on the general path and on the fast path.
TEST(Limit, DerivationStopsAtItsTimeLimit) {
    const Grammar g =
        parseGrammar("axiom: A(0)\nA(x) : x < 16 -> A(x+1)A(x+1)\nA(x) : x >= 16 -> A(x+1)\n");
    DeriveOptions o;
    o.generations = 1000; // 65,536 modules rewritten 984 times
    o.timeLimitSeconds = 1e-3;
    try {
        derive(g, o);
        FAIL() << "no time limit";
    } catch (const LimitExceeded& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("the derivation took more than its time limit of 0.001 s (stopped in "
                         "generation "),
                  std::string::npos)
            << m;
        EXPECT_NE(m.find("derive fewer generations or raise the limit (the lsystem node's "
                         "time_limit, sylva-cli expand --time-limit; at most 86400 s)"),
                  std::string::npos)
            << m;
    }
    const Grammar fast = parseGrammar("axiom: F\nF -> FF\n");
    o.generations = 24;
    o.timeLimitSeconds = 1e-6;
    EXPECT_THROW(derive(fast, o), LimitExceeded);
    // A derivation within its limit gives the same word as without one.
    o.generations = 10;
    o.timeLimitSeconds = kMaxDeriveTimeLimit;
    EXPECT_EQ(derive(fast, o).size(), 1024u);
    EXPECT_EQ(DeriveOptions{}.timeLimitSeconds, 300.0);
}

TEST(Limit, TimeLimitOutOfRangeIsInvalid) {
    const Grammar g = parseGrammar("axiom: F\n");
    for (double seconds : {0.0, -1.0, 86401.0, std::nan("")}) {
        DeriveOptions o;
        o.timeLimitSeconds = seconds;
        EXPECT_THROW(derive(g, o), InvalidInput) << seconds;
    }
}
