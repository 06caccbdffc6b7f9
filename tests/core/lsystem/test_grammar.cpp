// Grammar parser: settings, rule forms, and every diagnostic with its line and column.
#include <gtest/gtest.h>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

TEST(Grammar, ParsesTheHeaderAndRules) {
    const Grammar g =
        parseGrammar("# a comment\n"
                     "generations: 5\n"
                     "angle: 22.5          # degrees\n"
                     "step: 0.25\n"
                     "width: 0.3\n"
                     "width_factor: 0.6\n"
                     "seed: 42\n"
                     "ignore: + - F\n"
                     "define: r1 = 0.9\n"
                     "define: r2 = r1 * 2\n"
                     "axiom: A(1, 0.1)\n"
                     "A(l,w) : l > 0.1 -> !(w)F(l)[&(45)B(l*r1)]/(137.5)A(l*r1, w*0.7)\n"
                     "B(l) -> F(l * r2)\n",
                     "tree.lsys");
    EXPECT_EQ(g.fileName, "tree.lsys");
    EXPECT_EQ(g.generations, 5);
    EXPECT_DOUBLE_EQ(g.angleDegrees, 22.5);
    EXPECT_DOUBLE_EQ(g.step, 0.25);
    EXPECT_DOUBLE_EQ(g.width, 0.3);
    EXPECT_DOUBLE_EQ(g.widthFactor, 0.6);
    EXPECT_EQ(g.seed, 42u);
    EXPECT_TRUE(g.ignored['+'] && g.ignored['-'] && g.ignored['F']);
    EXPECT_FALSE(g.ignored['A']);
    EXPECT_DOUBLE_EQ(g.defines.at("r2"), 1.8);
    ASSERT_EQ(g.rules.size(), 2u);
    EXPECT_EQ(g.rules[0].line, 12);
    EXPECT_EQ(g.rules[0].column, 1);
    EXPECT_TRUE(g.rules[0].hasCondition);
    EXPECT_EQ(g.rules[0].formals, (std::vector<std::string>{"l", "w"}));
    EXPECT_EQ(g.rules[0].successor.modules.size(), 8u); // ! F [ & B ] / A
    EXPECT_TRUE(g.parametric);
    EXPECT_FALSE(g.contextSensitive);
    EXPECT_FALSE(g.stochastic);
}

TEST(Grammar, DefaultsWhenTheHeaderIsOmitted) {
    const Grammar g = parseGrammar("axiom: F\n");
    EXPECT_EQ(g.generations, 0);
    EXPECT_DOUBLE_EQ(g.angleDegrees, 90.0);
    EXPECT_DOUBLE_EQ(g.step, 1.0);
    EXPECT_DOUBLE_EQ(g.width, 0.1);
    EXPECT_DOUBLE_EQ(g.widthFactor, 0.7);
    EXPECT_EQ(g.seed, 0u);
    EXPECT_EQ(expand("axiom: F[+F]\n"), "F[+F]");
}

TEST(Grammar, RuleForms) {
    const Grammar g = parseGrammar("axiom: ABC\n"
                                   "A < B > C -> D\n"
                                   "B -> E : 0.25\n"
                                   "B -> F : 0.75\n"
                                   "C : * -> G\n"
                                   "- -> +\n");
    ASSERT_EQ(g.rules.size(), 5u);
    EXPECT_EQ(g.rules[0].left.size(), 1u);
    EXPECT_EQ(g.rules[0].right.size(), 1u);
    EXPECT_TRUE(g.rules[1].weighted);
    EXPECT_DOUBLE_EQ(g.rules[2].weight, 0.75);
    EXPECT_FALSE(g.rules[3].hasCondition);
    EXPECT_EQ(g.rules[4].predecessor.symbol, '-');
    // One context-sensitive group, one stochastic group of two, two deterministic groups.
    ASSERT_EQ(g.groups.size(), 4u);
    EXPECT_TRUE(g.groups[0].contextSensitive);
    EXPECT_TRUE(g.groups[1].stochastic);
    EXPECT_EQ(g.groups[1].rules.size(), 2u);
    // Context-sensitive groups come first for 'B'.
    ASSERT_EQ(g.groupsBySymbol['B'].size(), 2u);
    EXPECT_EQ(g.groupsBySymbol['B'][0], 0);
    EXPECT_EQ(g.groupsBySymbol['B'][1], 1);
}

TEST(Grammar, EmptySuccessorDeletes) {
    EXPECT_EQ(expand("axiom: ABA\nA ->\n", 1), "B");
}

namespace {

struct Expected {
    int line;
    int column;
    const char* fragment;
};

void expectOneDiagnostic(const std::string& text, Expected e) {
    const std::vector<Diagnostic> d = diagnose(text);
    ASSERT_EQ(d.size(), 1u) << text << (d.empty() ? "" : "\nfirst: " + d[0].format());
    EXPECT_EQ(d[0].file, "test.lsys");
    EXPECT_EQ(d[0].line, e.line) << d[0].format();
    EXPECT_EQ(d[0].column, e.column) << d[0].format();
    EXPECT_NE(d[0].message.find(e.fragment), std::string::npos) << d[0].format();
}

} // namespace

TEST(GrammarDiagnostics, SyntaxErrors) {
    expectOneDiagnostic("axiom: F\nF -> F(1\n", {2, 9, "expected ',' or ')'"});
    expectOneDiagnostic("axiom: F\nF F -> F\n", {2, 3, "single module"});
    expectOneDiagnostic("axiom: F\nF(x) : x > -> F\n", {2, 12, "expected a number"});
    expectOneDiagnostic("axiom: F\nF => G\n", {2, 1, "expected a setting"});
    expectOneDiagnostic("axiom: F\nF > -> G\n", {2, 5, "expected a right context"});
    expectOneDiagnostic("axiom: F\nF -> G 3\n", {2, 8, "'3' cannot be a module"});
    expectOneDiagnostic("axiom: F\nF -> G(1) : 0.5 0.5\n", {2, 17, "unexpected '0'"});
    expectOneDiagnostic("axiom: F\nangles: 4\n", {2, 1, "unknown setting 'angles'"});
    expectOneDiagnostic("axiom: F\nF() -> G\n", {2, 3, "expected a parameter name"});
    expectOneDiagnostic("axiom: F\nA(x, x) -> G\n", {2, 6, "appears twice"});
    expectOneDiagnostic("axiom: F\n[ -> G\n", {2, 1, "brackets cannot be rewritten"});
    expectOneDiagnostic("axiom: F\nA[ < B -> G\n", {2, 2, "not allowed in a left context"});
    expectOneDiagnostic("axiom: F\nignore: [\n", {2, 9, "brackets cannot be ignored"});
    expectOneDiagnostic("axiom: F\nF -> F\xc3\xa9\n", {2, 7, "plain ASCII"});
    expectOneDiagnostic("axiom: F\nF -> G()\n", {2, 6, "empty parameter list"});
    expectOneDiagnostic("axiom: F\ndefine: 3 = 4\n", {2, 9, "expected a name"});
    expectOneDiagnostic("axiom: F\ndefine: a = 1\ndefine: a = 2\n", {3, 9, "defined twice"});
    expectOneDiagnostic("axiom: F\nangle: 1\nangle: 2\n", {3, 1, "given twice (first at line 2)"});
    expectOneDiagnostic("axiom: F\ngenerations: 2.5\n", {2, 14, "whole number"});
    expectOneDiagnostic("axiom: F\ngenerations: -1\n", {2, 14, "whole number"});
    expectOneDiagnostic("axiom: F\ngenerations: 1001\n", {2, 14, "from 0 to 1000"});
    expectOneDiagnostic("axiom: F\nseed: -3\n", {2, 7, "seed must be a whole number"});
    expectOneDiagnostic("axiom: F\nstep: 0\n", {2, 7, "step must be > 0"});
    expectOneDiagnostic("axiom: F\nseed: rand(1, 2)\n", {2, 7, "seed must be a whole number"});
    expectOneDiagnostic("axiom: F\nangle: rand(1, 2)\n", {2, 8, "rand() is not allowed"});
}

TEST(GrammarDiagnostics, UnbalancedBrackets) {
    expectOneDiagnostic("axiom: F[F\n", {1, 9, "'[' is never closed in the axiom"});
    expectOneDiagnostic("axiom: F\nF -> F]F\n", {2, 7, "']' without '['"});
    expectOneDiagnostic("axiom: F\nF -> [[F]\n", {2, 6, "'[' is never closed in the successor"});
}

TEST(GrammarDiagnostics, UnknownConstants) {
    expectOneDiagnostic("axiom: A(1)\nA(x) -> A(x * r1)\n", {2, 15, "unknown constant 'r1'"});
    expectOneDiagnostic("axiom: A(q)\nA(x) -> A(x)\n", {1, 10, "unknown constant 'q'"});
    // Defines must come before their use.
    expectOneDiagnostic("axiom: F(r)\ndefine: r = 1\n", {1, 10, "unknown constant 'r'"});
}

TEST(GrammarDiagnostics, WrongParameterCounts) {
    expectOneDiagnostic("axiom: A(1)\nA(x, y) -> A(x)\n",
                        {2, 1, "module 'A' has 2 parameters here but 1 at line 1:8"});
    expectOneDiagnostic("axiom: A(1)B\nA(x) -> A(x)B(x)\n",
                        {2, 13, "module 'B' has 1 parameter here but 0 at line 1:12"});
    expectOneDiagnostic("axiom: A(1)\nB(x) < A(y) -> A(y)\nB -> C\n",
                        {3, 1, "module 'B' has 0 parameters here but 1 at line 2:1"});
    // Turtle symbols take 0 or 1 parameter (or none at all for brackets).
    expectOneDiagnostic("axiom: F(1, 2)\n", {1, 8, "'F' takes at most 1 parameter, got 2"});
    expectOneDiagnostic("axiom: F[(1)F]\n", {1, 9, "'[' takes no parameters"});
    // F with and without a length is fine.
    EXPECT_TRUE(diagnose("axiom: F F(2) +(30) +\nF(l) -> F(l*2)\n").empty());
}

TEST(GrammarDiagnostics, WeightsMustSumToOne) {
    expectOneDiagnostic("axiom: A\nA -> B : 0.5\nA -> C : 0.4\n",
                        {2, 1, "weights of the rules for 'A' (lines 2, 3) sum to 0.9, not 1"});
    expectOneDiagnostic("axiom: A\nA -> B : 0.5\n", {2, 1, "(line 2) sum to 0.5"});
    expectOneDiagnostic("axiom: A\nA -> B : 1.5\n", {2, 10, "a weight must be in (0, 1]"});
    expectOneDiagnostic("axiom: A\nA -> B\nA -> C\n", {3, 1, "give every alternative a weight"});
    // Within 1e-6 of 1 is accepted; groups differ by context or condition.
    EXPECT_TRUE(diagnose("axiom: A\nA -> B : 1/3\nA -> C : 1/3\nA -> D : 1/3\n").empty());
    EXPECT_TRUE(diagnose("axiom: A\nA -> B : 0.5\nA -> C : 0.4999995\n").empty());
    expectOneDiagnostic("axiom: A\nA -> B : 0.5\nA -> C : 0.499998\n", {2, 1, "sum to"});
    EXPECT_TRUE(diagnose("axiom: A(1)\nA(x) : x > 1 -> B : 0.5\nA(x) : x > 1 -> C : 0.5\n"
                         "A(x) : x <= 1 -> D\nB -> B\nC -> C\nD -> D\n")
                    .empty());
}

TEST(GrammarDiagnostics, EmptyOrMissingAxiom) {
    expectOneDiagnostic("generations: 2\naxiom:   # nothing\n", {2, 1, "the axiom is empty"});
    expectOneDiagnostic("generations: 2\nF -> FF\n", {0, 0, "no axiom"});
}

TEST(GrammarDiagnostics, CollectsAllDiagnostics) {
    const std::vector<Diagnostic> d = diagnose("generations: x\n"
                                               "axiom: F[\n"
                                               "F -> G(q)\n"
                                               "A -> B : 0.2\n");
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0].line, 1);
    EXPECT_EQ(d[1].line, 2);
    EXPECT_EQ(d[2].line, 3);
    EXPECT_EQ(d[3].line, 4);
    try {
        parseGrammar("axiom: F[\n", "g.lsys");
        FAIL() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
        EXPECT_STREQ(e.what(), "g.lsys:1:9: error: unbalanced brackets: '[' is never closed in "
                               "the axiom");
    }
}

// The editor checks a grammar as the user types: every error comes back with its position,
// nothing is thrown, and a good grammar parses exactly as parseGrammar() parses it.
TEST(Grammar, CheckCollectsEveryDiagnosticWithoutThrowing) {
    const std::string text = "axiom: F\n"
                             "F -> F[+F\n" // line 2: unbalanced bracket
                             "angle: 25\n"
                             "X(a -> F\n"          // line 4: unclosed parameter list
                             "generations: abc\n"; // line 5: not a number
    sylva::lsys::GrammarCheck check;
    ASSERT_NO_THROW(check = sylva::lsys::checkGrammar(text, "t.lsys"));
    EXPECT_FALSE(check.ok());
    ASSERT_EQ(check.diagnostics.size(), 3u);
    EXPECT_EQ(check.diagnostics[0].line, 2);
    EXPECT_EQ(check.diagnostics[1].line, 4);
    EXPECT_EQ(check.diagnostics[2].line, 5);
    EXPECT_EQ(check.diagnostics[0].column, 7);
    EXPECT_EQ(check.diagnostics[1].column, 5);
    EXPECT_EQ(check.diagnostics[2].column, 14);
    for (const auto& d : check.diagnostics) {
        EXPECT_EQ(d.file, "t.lsys");
        EXPECT_FALSE(d.message.empty());
        EXPECT_GT(d.column, 0);
    }
    // The same diagnostics parseGrammar throws.
    try {
        sylva::lsys::parseGrammar(text, "t.lsys");
        FAIL();
    } catch (const sylva::InvalidInput& e) {
        ASSERT_EQ(e.diagnostics().size(), 3u);
        EXPECT_EQ(e.diagnostics()[1].message, check.diagnostics[1].message);
    }
    const auto good = sylva::lsys::checkGrammar("axiom: F\nF -> F[+F]F\n");
    EXPECT_TRUE(good.ok());
    EXPECT_EQ(good.grammar.rules.size(), 1u);
}
