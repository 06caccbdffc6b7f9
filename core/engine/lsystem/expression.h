#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/util/random.h"

namespace sylva::lsys {

class Scanner;

enum class ExprOp : std::uint8_t {
    Const, // push value
    Arg,   // push args[index]
    Neg,
    Not,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Sin, // trigonometric functions take their argument in degrees, like angle:
    Cos,
    Tan,
    Sqrt,
    Abs,
    Floor,
    Exp,
    Log,
    Min,
    Max,
    Rand, // uniform in [a, b) from the derivation's seeded Rng
};

struct ExprInstr {
    ExprOp op = ExprOp::Const;
    std::int32_t index = 0;  ///< Arg: parameter slot
    std::int32_t column = 0; ///< source column of the operator, for runtime diagnostics
    double value = 0.0;      ///< Const: the value
};

/// Why an evaluation failed; `column` is the source column of the failing operator.
struct ExprError {
    enum Kind { None, DivisionByZero, NotFinite } kind = None;
    int column = 0;
};

/// A compiled expression: postfix (RPN) code for a small stack machine. Constant
/// sub-expressions are folded at compile time, so `l * r1` with `define: r1 = 0.9` is two
/// instructions and a literal is one.
class Expression {
public:
    /// Evaluates with the formal parameters bound in \p args. Returns false (and fills
    /// \p error) on division by zero or a non-finite result; \p rng feeds rand().
    bool evaluate(const double* args, Rng& rng, double& result, ExprError& error) const;

    bool isConstant() const { return mCode.size() == 1 && mCode[0].op == ExprOp::Const; }
    double constantValue() const { return mCode.empty() ? 0.0 : mCode[0].value; }
    bool usesRand() const;
    int line() const { return mLine; }
    int column() const { return mColumn; }
    const std::vector<ExprInstr>& code() const { return mCode; }

private:
    friend class ExpressionCompiler;
    std::vector<ExprInstr> mCode;
    int mLine = 0;
    int mColumn = 0;
};

/// What names an expression may refer to.
struct ExprScope {
    const std::vector<std::string>* formals = nullptr; ///< parameter slot names (rule formals)
    const std::map<std::string, double>* defines = nullptr;
    bool allowRand = true;
    const char* randForbiddenReason = "";
};

/// Compiles the expression at the scanner's cursor; it ends before `,` `)` `:` `->`, a comment
/// or the end of the line. Errors go to the scanner's diagnostics; returns false if any.
bool compileExpression(Scanner& scanner, const ExprScope& scope, Expression& out);

/// The largest operand stack an expression may need (expressions nested deeper are rejected).
inline constexpr int kMaxExprStack = 64;

/// The deepest nesting of parentheses, unary operators and '^' an expression may have (the
/// compiler recurses once per level).
inline constexpr int kMaxExprNesting = 256;

} // namespace sylva::lsys
