// Parametric rules: conditions, expressions, defines, ABOP's worked examples, runtime errors.
#include <gtest/gtest.h>

#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

TEST(Parametric, AbopFigure130Derivation) {
    // ABOP §1.10.1, the sample derivation of fig. 1.30.
    const std::string g = "axiom: B(2)A(4,4)\n"
                          "A(x,y) : y <= 3 -> A(x*2, x+y)\n"
                          "A(x,y) : y > 3 -> B(x)A(x/y, 0)\n"
                          "B(x) : x < 1 -> C\n"
                          "B(x) : x >= 1 -> B(x-1)\n";
    EXPECT_EQ(expand(g, 1), "B(1)B(4)A(1,0)");
    EXPECT_EQ(expand(g, 2), "B(0)B(3)A(2,1)");
    EXPECT_EQ(expand(g, 3), "CB(2)A(4,3)");
    EXPECT_EQ(expand(g, 4), "CB(1)A(8,7)");
    EXPECT_EQ(expand(g, 5), "CB(0)B(8)A(1.1428571428571428,0)");
}

TEST(Parametric, IssueExampleRuleWithDefinesAndCondition) {
    const std::string g = "define: r1 = 0.5\n"
                          "axiom: A(1, 0.1)\n"
                          "A(l,w) : l > 0.1 -> !(w)F(l)[&(45)B(l*r1)]/(137.5)A(l*r1, w*0.7)\n";
    EXPECT_EQ(expand(g, 1), "!(0.1)F(1)[&(45)B(0.5)]/(137.5)A(0.5,0.06999999999999999)");
    // l = 0.125 after three steps; the fourth still applies (0.125 > 0.1), the fifth not.
    const std::string w4 = expand(g, 4);
    const std::string w5 = expand(g, 5);
    EXPECT_EQ(countOf(w4, 'F'), 4u);
    EXPECT_EQ(countOf(w5, 'F'), 4u);
    EXPECT_NE(w5.find("A(0.0625,"), std::string::npos) << w5;
}

TEST(Parametric, FirstMatchingRuleInFileOrder) {
    const std::string g = "axiom: A(5)\nA(x) : x > 3 -> B\nA(x) : x > 1 -> C\nA(x) -> D\n";
    EXPECT_EQ(expand(g, 1), "B");
    EXPECT_EQ(expand("axiom: A(2)\nA(x) : x > 3 -> B\nA(x) : x > 1 -> C\nA(x) -> D\n", 1), "C");
    EXPECT_EQ(expand("axiom: A(0)\nA(x) : x > 3 -> B\nA(x) : x > 1 -> C\nA(x) -> D\n", 1), "D");
    // No rule's condition holds: the module is copied unchanged.
    EXPECT_EQ(expand("axiom: A(0)\nA(x) : x > 3 -> B\n", 1), "A(0)");
}

TEST(Parametric, TurtleSymbolsMatchByArity) {
    // F(l) rules do not touch a plain F, and vice versa.
    EXPECT_EQ(expand("axiom: F F(2)\nF(l) -> F(l*3)\n", 1), "FF(6)");
    EXPECT_EQ(expand("axiom: F F(2)\nF -> FF\n", 1), "FFF(2)");
}

TEST(Parametric, ExpressionFeaturesInRules) {
    EXPECT_EQ(expand("axiom: A(9)\nA(x) -> Q(sqrt(x), max(x, 10), floor(x/2), -x^2)\n", 1),
              "Q(3,10,4,-81)");
    EXPECT_EQ(expand("axiom: A(1,0)\nA(x,y) : x == 1 && !(y > 0) || y == 5 -> B\n", 1), "B");
}

TEST(Parametric, NonParametricWordHasNoParameterArrays) {
    const ModuleString s = derive(parseGrammar("axiom: A(1)\nA(x) -> FF\n"), options(1));
    EXPECT_EQ(s.symbols, "FF");
    EXPECT_FALSE(s.hasParams());
    EXPECT_TRUE(s.params.empty());
}

TEST(Parametric, DivisionByZeroNamesTheRule) {
    const Grammar g = parseGrammar("axiom: A(2)\nA(x) -> A(x - 1)B(1 / (x - 1))\n", "div.lsys");
    EXPECT_EQ(formatModules(derive(g, options(1))), "A(1)B(1)");
    try {
        derive(g, options(2));
        FAIL() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
        ASSERT_EQ(e.diagnostics().size(), 1u);
        const Diagnostic& d = e.diagnostics()[0];
        EXPECT_EQ(d.file, "div.lsys");
        EXPECT_EQ(d.line, 2);
        EXPECT_EQ(d.column, 21);
        EXPECT_NE(d.message.find("division by zero in the rule 'A(x) -> A(x - 1)B(1 / (x - 1))' "
                                 "(line 2) at generation 2"),
                  std::string::npos)
            << d.message;
    }
    // In a condition, too.
    const Grammar c = parseGrammar("axiom: A(0)\nA(x) : 1 / x > 2 -> B\n");
    try {
        derive(c, options(1));
        FAIL() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.diagnostics()[0].line, 2);
        EXPECT_EQ(e.diagnostics()[0].column, 10);
    }
    // A non-finite value (sqrt of a negative number) is an error as well.
    EXPECT_THROW(derive(parseGrammar("axiom: A(-1)\nA(x) -> A(sqrt(x))\n"), options(1)),
                 InvalidInput);
}
