// Expression compiler and evaluator: precedence, functions (degrees), folding, rand, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "engine/lsystem/expression.h"
#include "engine/lsystem/scanner.h"

using namespace sylva;
using namespace sylva::lsys;

namespace {

struct Compiled {
    bool ok = false;
    Expression expr;
    std::vector<Diagnostic> diagnostics;
};

Compiled compile(const std::string& text, const std::vector<std::string>& formals = {},
                 const std::map<std::string, double>& defines = {}, bool allowRand = true) {
    Compiled c;
    const std::string file = "e";
    Scanner s(text, 1, file, c.diagnostics);
    ExprScope scope;
    scope.formals = &formals;
    scope.defines = &defines;
    scope.allowRand = allowRand;
    scope.randForbiddenReason = "test";
    c.ok = compileExpression(s, scope, c.expr);
    return c;
}

double eval(const std::string& text, std::vector<double> args = {},
            const std::vector<std::string>& formals = {}) {
    Compiled c = compile(text, formals);
    EXPECT_TRUE(c.ok) << text << ": " << (c.diagnostics.empty() ? "" : c.diagnostics[0].format());
    Rng rng(1);
    double v = NAN;
    ExprError err;
    EXPECT_TRUE(c.expr.evaluate(args.data(), rng, v, err)) << text;
    return v;
}

} // namespace

TEST(Expression, ArithmeticPrecedence) {
    EXPECT_DOUBLE_EQ(eval("1 + 2 * 3"), 7.0);
    EXPECT_DOUBLE_EQ(eval("(1 + 2) * 3"), 9.0);
    EXPECT_DOUBLE_EQ(eval("10 - 4 - 3"), 3.0); // left-associative
    EXPECT_DOUBLE_EQ(eval("8 / 4 / 2"), 1.0);
    EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 512.0); // right-associative
    EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), -4.0);     // ^ binds tighter than unary minus
    EXPECT_DOUBLE_EQ(eval("2 * -3"), -6.0);
    EXPECT_DOUBLE_EQ(eval("1.5e2 + .5"), 150.5);
}

TEST(Expression, ComparisonsAndLogic) {
    EXPECT_EQ(eval("1 < 2"), 1.0);
    EXPECT_EQ(eval("2 <= 2"), 1.0);
    EXPECT_EQ(eval("3 > 4"), 0.0);
    EXPECT_EQ(eval("4 >= 5"), 0.0);
    EXPECT_EQ(eval("3 == 3"), 1.0);
    EXPECT_EQ(eval("3 != 3"), 0.0);
    EXPECT_EQ(eval("1 < 2 && 2 < 1"), 0.0);
    EXPECT_EQ(eval("1 < 2 || 2 < 1"), 1.0);
    EXPECT_EQ(eval("!0"), 1.0);
    EXPECT_EQ(eval("!(1 + 1 == 2)"), 0.0);
    // && binds tighter than ||; comparisons tighter than &&.
    EXPECT_EQ(eval("1 || 0 && 0"), 1.0);
    EXPECT_EQ(eval("1 + 1 > 1 && 2 > 1"), 1.0);
}

TEST(Expression, FunctionsTakeDegrees) {
    EXPECT_NEAR(eval("sin(90)"), 1.0, 1e-15);
    EXPECT_NEAR(eval("cos(180)"), -1.0, 1e-15);
    EXPECT_NEAR(eval("tan(45)"), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(eval("sqrt(16)"), 4.0);
    EXPECT_DOUBLE_EQ(eval("abs(-3.5)"), 3.5);
    EXPECT_DOUBLE_EQ(eval("min(3, -2)"), -2.0);
    EXPECT_DOUBLE_EQ(eval("max(3, -2)"), 3.0);
    EXPECT_DOUBLE_EQ(eval("floor(-1.5)"), -2.0);
    EXPECT_NEAR(eval("exp(1)"), std::exp(1.0), 1e-15);
    EXPECT_NEAR(eval("log(exp(2))"), 2.0, 1e-15);
}

TEST(Expression, FormalsAndDefines) {
    EXPECT_DOUBLE_EQ(eval("l * 2 + w", {3.0, 0.5}, {"l", "w"}), 6.5);
    Compiled c = compile("l * r1", {"l"}, {{"r1", 0.9}});
    ASSERT_TRUE(c.ok);
    // The define is folded into a constant: Arg, Const, Mul.
    EXPECT_EQ(c.expr.code().size(), 3u);
    // A formal shadows a define of the same name.
    Compiled s = compile("x", {"x"}, {{"x", 7.0}});
    ASSERT_TRUE(s.ok);
    EXPECT_EQ(s.expr.code()[0].op, ExprOp::Arg);
}

TEST(Expression, ConstantFolding) {
    Compiled c = compile("2 * (3 + 4) - sin(30) * 2");
    ASSERT_TRUE(c.ok);
    ASSERT_TRUE(c.expr.isConstant());
    EXPECT_NEAR(c.expr.constantValue(), 13.0, 1e-12);
}

TEST(Expression, RandIsSeededAndInRange) {
    Compiled c = compile("rand(2, 5)");
    ASSERT_TRUE(c.ok);
    EXPECT_FALSE(c.expr.isConstant());
    EXPECT_TRUE(c.expr.usesRand());
    Rng a(42), b(42);
    for (int i = 0; i < 1000; ++i) {
        double va = 0, vb = 0;
        ExprError err;
        ASSERT_TRUE(c.expr.evaluate(nullptr, a, va, err));
        ASSERT_TRUE(c.expr.evaluate(nullptr, b, vb, err));
        EXPECT_EQ(va, vb);
        EXPECT_GE(va, 2.0);
        EXPECT_LT(va, 5.0);
    }
    Compiled forbidden = compile("rand(0, 1)", {}, {}, false);
    EXPECT_FALSE(forbidden.ok);
    ASSERT_EQ(forbidden.diagnostics.size(), 1u);
    EXPECT_EQ(forbidden.diagnostics[0].column, 1);
}

TEST(Expression, RuntimeDivisionByZeroReportsTheOperatorColumn) {
    Compiled c = compile("1 + 2 / x", {"x"});
    ASSERT_TRUE(c.ok);
    const double args[] = {0.0};
    Rng rng(0);
    double v = 0;
    ExprError err;
    EXPECT_FALSE(c.expr.evaluate(args, rng, v, err));
    EXPECT_EQ(err.kind, ExprError::DivisionByZero);
    EXPECT_EQ(err.column, 7);
    const double ok[] = {4.0};
    EXPECT_TRUE(c.expr.evaluate(ok, rng, v, err));
    EXPECT_DOUBLE_EQ(v, 1.5);
}

TEST(Expression, NonFiniteResultIsAnError) {
    Compiled c = compile("sqrt(x)", {"x"});
    ASSERT_TRUE(c.ok);
    const double args[] = {-1.0};
    Rng rng(0);
    double v = 0;
    ExprError err;
    EXPECT_FALSE(c.expr.evaluate(args, rng, v, err));
    EXPECT_EQ(err.kind, ExprError::NotFinite);
}

TEST(Expression, CompileErrorsCarryColumns) {
    struct Case {
        const char* text;
        int column;
        const char* fragment;
    };
    const Case cases[] = {
        {"1 + q", 5, "unknown constant 'q'"},
        {"foo(1)", 1, "unknown function 'foo'"},
        {"min(1)", 1, "'min' takes 2 arguments, got 1"},
        {"1 / 0", 3, "division by zero"},
        {"(1 + 2", 7, "expected ')'"},
        {"1 + ", 5, "expected a number"},
        {"1 $ 2", 3, "unexpected '$'"},
        {"log(0)", 1, "not a finite number"},
    };
    for (const Case& k : cases) {
        Compiled c = compile(k.text);
        EXPECT_FALSE(c.ok) << k.text;
        ASSERT_FALSE(c.diagnostics.empty()) << k.text;
        EXPECT_EQ(c.diagnostics[0].line, 1) << k.text;
        EXPECT_EQ(c.diagnostics[0].column, k.column) << k.text;
        EXPECT_NE(c.diagnostics[0].message.find(k.fragment), std::string::npos)
            << k.text << " -> " << c.diagnostics[0].message;
    }
}

TEST(Expression, StopsAtDelimiters) {
    // An expression ends before ',', ')', ':' and '->', leaving them to the grammar parser.
    std::vector<Diagnostic> d;
    const std::string file = "e";
    const std::string text = "x > 1 -> B";
    Scanner s(text, 1, file, d);
    const std::vector<std::string> formals{"x"};
    ExprScope scope;
    scope.formals = &formals;
    Expression e;
    ASSERT_TRUE(compileExpression(s, scope, e));
    EXPECT_TRUE(s.atArrow());
    EXPECT_EQ(s.column(), 7);
}

// A grammar line of 200,000 '(' (or '-', or '2^') overflowed the stack of the recursive
// compiler and crashed sylva-cli: nesting deeper than kMaxExprNesting is a diagnostic.
TEST(Expression, NestingIsLimited) {
    const std::string ok = std::string(200, '(') + "1" + std::string(200, ')');
    EXPECT_EQ(eval(ok), 1.0);
    EXPECT_EQ(eval(std::string(200, '-') + "3"), 3.0);
    for (const std::string& deep :
         {std::string(200'000, '(') + "1" + std::string(200'000, ')'),
          std::string(200'000, '-') + "1", std::string(200'000, '!') + "1"}) {
        Compiled c = compile(deep);
        EXPECT_FALSE(c.ok);
        ASSERT_EQ(c.diagnostics.size(), 1u);
        EXPECT_EQ(c.diagnostics[0].message,
                  "expression is nested too deeply (more than 256 levels)");
        EXPECT_EQ(c.diagnostics[0].column, kMaxExprNesting + 1);
    }
    std::string pow;
    for (int i = 0; i < 100'000; ++i)
        pow += "2^";
    Compiled p = compile(pow + "1");
    EXPECT_FALSE(p.ok);
    ASSERT_EQ(p.diagnostics.size(), 1u); // not one more per folded level
    EXPECT_EQ(p.diagnostics[0].message, "expression is nested too deeply (more than 256 levels)");
}
