// Derivation: hand-checked words, the table-driven fast path against a naive rewriter, and the
// general path against the same oracle.
#include <gtest/gtest.h>

#include <map>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

namespace {

/// The naive oracle: one std::string concatenation per symbol.
std::string naiveRewrite(std::string word, const std::map<char, std::string>& rules, int n) {
    for (int i = 0; i < n; ++i) {
        std::string next;
        for (char c : word) {
            auto it = rules.find(c);
            next += it == rules.end() ? std::string(1, c) : it->second;
        }
        word = std::move(next);
    }
    return word;
}

class CancelAfter : public Progress {
public:
    explicit CancelAfter(int reports) : mLeft(reports) {}
    void report(double, std::string_view) override { --mLeft; }
    bool isCancelled() const override { return mLeft <= 0; }

private:
    int mLeft;
};

} // namespace

TEST(Derivation, AlgaeGivesFibonacciLengths) {
    const Grammar g = parseGrammar("axiom: a\na -> ab\nb -> a\n");
    EXPECT_EQ(formatModules(derive(g, options(0))), "a");
    EXPECT_EQ(formatModules(derive(g, options(1))), "ab");
    EXPECT_EQ(formatModules(derive(g, options(2))), "aba");
    EXPECT_EQ(formatModules(derive(g, options(3))), "abaab");
    EXPECT_EQ(formatModules(derive(g, options(4))), "abaababa");
    std::size_t fib[30] = {1, 2};
    for (int i = 2; i < 30; ++i)
        fib[i] = fib[i - 1] + fib[i - 2];
    for (int n = 0; n < 30; ++n) {
        const ModuleString s = derive(g, options(n));
        ASSERT_EQ(s.size(), fib[n]) << n;
        EXPECT_FALSE(s.hasParams());
    }
}

TEST(Derivation, EdgeRewritingGivesPowersOfFive) {
    const Grammar g = parseGrammar("axiom: F\nF -> F[+F]F[-F]F\n");
    std::size_t fives = 1;
    for (int n = 0; n <= 8; ++n) {
        const std::string s = formatModules(derive(g, options(n)));
        EXPECT_EQ(countOf(s, 'F'), fives) << n;
        EXPECT_EQ(countOf(s, '['), countOf(s, ']'));
        fives *= 5;
    }
    EXPECT_EQ(formatModules(derive(g, options(2))),
              "F[+F]F[-F]F[+F[+F]F[-F]F]F[+F]F[-F]F[-F[+F]F[-F]F]F[+F]F[-F]F");
}

TEST(Derivation, FastPathMatchesNaiveRewriter) {
    struct Case {
        const char* grammar;
        std::string axiom;
        std::map<char, std::string> rules;
        int generations;
    };
    const Case cases[] = {
        {"axiom: F\nF -> F[+F]F[-F]F\n", "F", {{'F', "F[+F]F[-F]F"}}, 6},
        {"axiom: X\nX -> F[+X]F[-X]+X\nF -> FF\n", "X", {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, 7},
        // A successor longer than 32 symbols takes the variable-length copy.
        {"axiom: AB\nA -> BABABABABABABABABABABABABABABABABA\nB ->\n",
         "AB",
         {{'A', "BABABABABABABABABABABABABABABABABA"}, {'B', ""}},
         5},
        // Between 17 and 32 symbols.
        {"axiom: A-A\nA -> A+BA-BA+BA-B+A-BA+B\nB -> BB\n",
         "A-A",
         {{'A', "A+BA-BA+BA-B+A-BA+B"}, {'B', "BB"}},
         5},
    };
    for (const Case& c : cases) {
        const Grammar g = parseGrammar(c.grammar);
        for (int n = 0; n <= c.generations; ++n)
            ASSERT_EQ(formatModules(derive(g, options(n))), naiveRewrite(c.axiom, c.rules, n))
                << c.grammar << " n=" << n;
    }
}

TEST(Derivation, GeneralPathMatchesNaiveRewriter) {
    // A parametric bystander module forces the general path for the same F rule.
    const Grammar g = parseGrammar("axiom: Z(1)F\nF -> F[+F]F[-F]F\nZ(x) -> Z(x + 1)\n");
    for (int n = 0; n <= 5; ++n) {
        const std::string s = formatModules(derive(g, options(n)));
        const std::string expected =
            "Z(" + std::to_string(n + 1) + ")" + naiveRewrite("F", {{'F', "F[+F]F[-F]F"}}, n);
        ASSERT_EQ(s, expected) << n;
    }
}

TEST(Derivation, OptionsOverrideTheGrammar) {
    const Grammar g = parseGrammar("generations: 3\naxiom: a\na -> ab\nb -> a\n");
    EXPECT_EQ(formatModules(derive(g)), "abaab");
    EXPECT_EQ(formatModules(derive(g, options(1))), "ab");
    EXPECT_THROW(derive(g, options(-1)), InvalidInput);
}

TEST(Derivation, UnmatchedModulesAreCopiedWithTheirParameters) {
    EXPECT_EQ(expand("axiom: A(1.5)B(2,3)C\nC -> D\n", 1), "A(1.5)B(2,3)D");
}

TEST(Derivation, FormatModulesUsesShortestRoundTrip) {
    ModuleString s;
    s.symbols = "A+F";
    s.paramCounts = {2, 0, 1};
    s.params = {0.1, 1e21, -2.5};
    EXPECT_EQ(formatModules(s), "A(0.1,1e+21)+F(-2.5)");
    EXPECT_EQ(expand("axiom: A(4)B(3)F[+F]\n"), "A(4)B(3)F[+F]");
}

TEST(Derivation, CancellationStopsBetweenGenerations) {
    const Grammar g = parseGrammar("axiom: F\nF -> FF\n");
    CancelAfter fast(2);
    EXPECT_THROW(derive(g, options(10), fast), Cancelled);
    const Grammar p = parseGrammar("axiom: A(1)\nA(x) -> A(x)A(x)\n");
    CancelAfter slow(2);
    EXPECT_THROW(derive(p, options(10), slow), Cancelled);
}

namespace {

/// The traced oracle: each module with the line of the rule that last wrote it (the axiom's line
/// for modules no rule wrote), rewritten naively.
using Traced = std::vector<std::pair<char, int>>;
Traced naiveTraced(const std::string& axiom, int axiomLine,
                   const std::map<char, std::pair<std::string, int>>& rules, int n) {
    Traced word;
    for (char c : axiom)
        word.push_back({c, axiomLine});
    for (int i = 0; i < n; ++i) {
        Traced next;
        for (const auto& [c, line] : word) {
            auto it = rules.find(c);
            if (it == rules.end()) {
                next.push_back({c, line});
                continue;
            }
            for (char s : it->second.first)
                next.push_back({s, it->second.second});
        }
        word = std::move(next);
    }
    return word;
}

} // namespace

TEST(Derivation, TracedRulesNameTheLineThatWroteEachModule) {
    // Hand-checked at two generations: F F from line 3, the rest of X's successors from line 2.
    const Grammar g = parseGrammar("# comment\naxiom: X\nX -> F[+X]-X\nF -> FF\n");
    EXPECT_EQ(g.axiomLine, 2);
    DeriveOptions traced = options(2);
    traced.traceRules = true;
    const ModuleString w = derive(g, traced);
    EXPECT_EQ(formatModules(w), "FF[+F[+X]-X]-F[+X]-X");
    const std::vector<std::int32_t> expected = {4, 4, 3, 3, 3, 3, 3, 3, 3, 3,
                                                3, 3, 3, 3, 3, 3, 3, 3, 3, 3};
    EXPECT_EQ(w.origins, expected);
    // Untraced words carry no origins, and tracing changes nothing else.
    const ModuleString plain = derive(g, options(2));
    EXPECT_TRUE(plain.origins.empty());
    EXPECT_EQ(formatModules(plain), formatModules(w));
    // The axiom alone: its own line.
    traced.generations = 0;
    EXPECT_EQ(derive(g, traced).origins, std::vector<std::int32_t>{2});
}

TEST(Derivation, TracedDerivationMatchesTheNaiveTracer) {
    // A grammar the fast path serves (tracing takes the general path: same word), with a symbol
    // that no rule rewrites after its first generation ('A' -> "B", B has no rule).
    const Grammar g = parseGrammar("axiom: AX\nX -> F[+X]F[-X]A\nF -> FF\nA -> B\n");
    for (int n = 0; n <= 6; ++n) {
        DeriveOptions o = options(n);
        o.traceRules = true;
        const ModuleString w = derive(g, o);
        const Traced expected =
            naiveTraced("AX", 1, {{'X', {"F[+X]F[-X]A", 2}}, {'F', {"FF", 3}}, {'A', {"B", 4}}}, n);
        ASSERT_EQ(w.size(), expected.size()) << n;
        ASSERT_EQ(w.origins.size(), w.size()) << n;
        for (std::size_t i = 0; i < w.size(); ++i) {
            ASSERT_EQ(w.symbols[i], expected[i].first) << n << " at " << i;
            ASSERT_EQ(w.origins[i], expected[i].second) << n << " at " << i;
        }
        EXPECT_EQ(formatModules(w), formatModules(derive(g, options(n))));
    }
}

TEST(Derivation, TracedStochasticAndParametricWordsAreUnchanged) {
    const Grammar stochastic = parseGrammar("axiom: F\nF -> F[+F]F : 0.5\nF -> F[-F] : 0.5\n");
    const Grammar parametric =
        parseGrammar("axiom: A(1)\nA(x) : x < 4 -> F(x)[+A(x + 1)]A(x + 1)\nA(x) -> F(x)\n");
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        DeriveOptions o = options(5, seed);
        const ModuleString plain = derive(stochastic, o);
        o.traceRules = true;
        const ModuleString w = derive(stochastic, o);
        EXPECT_EQ(formatModules(w), formatModules(plain)) << seed;
        ASSERT_EQ(w.origins.size(), w.size());
        std::map<int, int> lines;
        for (std::int32_t l : w.origins)
            ++lines[l];
        // Both rules were drawn; every module comes from one of them (F is always rewritten).
        EXPECT_GT(lines[2], 0);
        EXPECT_GT(lines[3], 0);
        EXPECT_EQ(lines[2] + lines[3], static_cast<int>(w.size()));
    }
    DeriveOptions o = options(4);
    o.traceRules = true;
    const ModuleString w = derive(parametric, o);
    EXPECT_EQ(formatModules(w), formatModules(derive(parametric, options(4))));
    // The last generation rewrote A(4) with the second rule (line 3): F(4) there.
    for (std::size_t i = 0, p = 0; i < w.size(); p += w.paramCounts[i], ++i)
        if (w.symbols[i] == 'F') {
            EXPECT_EQ(w.origins[i], w.params[p] == 4.0 ? 3 : 2) << i;
        }
}
