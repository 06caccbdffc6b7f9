#include "engine/lsystem/expression.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include "engine/lsystem/scanner.h"

namespace sylva::lsys {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

bool isIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
    return isIdentStart(c) || (c >= '0' && c <= '9');
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

int arityOf(ExprOp op) {
    switch (op) {
    case ExprOp::Const:
    case ExprOp::Arg:
        return 0;
    case ExprOp::Neg:
    case ExprOp::Not:
    case ExprOp::Sin:
    case ExprOp::Cos:
    case ExprOp::Tan:
    case ExprOp::Sqrt:
    case ExprOp::Abs:
    case ExprOp::Floor:
    case ExprOp::Exp:
    case ExprOp::Log:
        return 1;
    default:
        return 2;
    }
}

/// Applies a unary or binary operator; false on division by zero.
bool apply(ExprOp op, double a, double b, double& out) {
    switch (op) {
    case ExprOp::Neg:
        out = -a;
        return true;
    case ExprOp::Not:
        out = a == 0.0 ? 1.0 : 0.0;
        return true;
    case ExprOp::Add:
        out = a + b;
        return true;
    case ExprOp::Sub:
        out = a - b;
        return true;
    case ExprOp::Mul:
        out = a * b;
        return true;
    case ExprOp::Div:
        if (b == 0.0) return false;
        out = a / b;
        return true;
    case ExprOp::Pow:
        out = std::pow(a, b);
        return true;
    case ExprOp::Lt:
        out = a < b;
        return true;
    case ExprOp::Le:
        out = a <= b;
        return true;
    case ExprOp::Gt:
        out = a > b;
        return true;
    case ExprOp::Ge:
        out = a >= b;
        return true;
    case ExprOp::Eq:
        out = a == b;
        return true;
    case ExprOp::Ne:
        out = a != b;
        return true;
    case ExprOp::And:
        out = (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
        return true;
    case ExprOp::Or:
        out = (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
        return true;
    case ExprOp::Sin:
        out = std::sin(a * kDegToRad);
        return true;
    case ExprOp::Cos:
        out = std::cos(a * kDegToRad);
        return true;
    case ExprOp::Tan:
        out = std::tan(a * kDegToRad);
        return true;
    case ExprOp::Sqrt:
        out = std::sqrt(a);
        return true;
    case ExprOp::Abs:
        out = std::fabs(a);
        return true;
    case ExprOp::Floor:
        out = std::floor(a);
        return true;
    case ExprOp::Exp:
        out = std::exp(a);
        return true;
    case ExprOp::Log:
        out = std::log(a);
        return true;
    case ExprOp::Min:
        out = std::fmin(a, b);
        return true;
    case ExprOp::Max:
        out = std::fmax(a, b);
        return true;
    default:
        out = 0.0;
        return true;
    }
}

struct FunctionInfo {
    const char* name;
    ExprOp op;
    int arity;
};
constexpr FunctionInfo kFunctions[] = {
    {"sin", ExprOp::Sin, 1},   {"cos", ExprOp::Cos, 1},   {"tan", ExprOp::Tan, 1},
    {"sqrt", ExprOp::Sqrt, 1}, {"abs", ExprOp::Abs, 1},   {"floor", ExprOp::Floor, 1},
    {"exp", ExprOp::Exp, 1},   {"log", ExprOp::Log, 1},   {"min", ExprOp::Min, 2},
    {"max", ExprOp::Max, 2},   {"rand", ExprOp::Rand, 2},
};

} // namespace

bool Expression::usesRand() const {
    for (const ExprInstr& i : mCode)
        if (i.op == ExprOp::Rand) return true;
    return false;
}

bool Expression::evaluate(const double* args, Rng& rng, double& result, ExprError& error) const {
    double stack[kMaxExprStack];
    int sp = 0;
    for (const ExprInstr& in : mCode) {
        switch (in.op) {
        case ExprOp::Const:
            stack[sp++] = in.value;
            break;
        case ExprOp::Arg:
            stack[sp++] = args[in.index];
            break;
        case ExprOp::Rand: {
            const double lo = stack[sp - 2];
            const double hi = stack[sp - 1];
            --sp;
            stack[sp - 1] = rng.uniform(lo, hi);
            break;
        }
        default: {
            const int n = arityOf(in.op);
            const double a = stack[sp - n];
            const double b = n == 2 ? stack[sp - 1] : 0.0;
            sp -= n - 1;
            if (!apply(in.op, a, b, stack[sp - 1])) {
                error = {ExprError::DivisionByZero, in.column};
                return false;
            }
        }
        }
    }
    result = stack[0];
    if (!std::isfinite(result)) {
        error = {ExprError::NotFinite, mColumn};
        return false;
    }
    return true;
}

/// Recursive-descent (precedence climbing) compiler to RPN with constant folding.
/// Precedence, low to high: || , && , == != , < <= > >= , + - , * / , unary - ! , ^ (right).
class ExpressionCompiler {
public:
    ExpressionCompiler(Scanner& s, const ExprScope& scope) : mS(s), mScope(scope) {}

    bool run(Expression& out) {
        const std::size_t errorsBefore = mS.errorCount();
        mS.skipSpaces();
        out.mLine = mS.line();
        out.mColumn = mS.column();
        if (atStop()) {
            mS.error("expected an expression, found " + mS.describeHere());
            return false;
        }
        Code code = parseBinary(0);
        if (mS.errorCount() != errorsBefore) return false;
        // Stack depth check.
        int depth = 0, maxDepth = 0;
        for (const ExprInstr& i : code) {
            depth += 1 - (i.op == ExprOp::Const || i.op == ExprOp::Arg ? 0 : arityOf(i.op));
            maxDepth = std::max(maxDepth, depth);
        }
        if (maxDepth > kMaxExprStack) {
            mS.error(out.mColumn, "expression is nested too deeply");
            return false;
        }
        out.mCode = std::move(code);
        return true;
    }

private:
    using Code = std::vector<ExprInstr>;

    bool atStop() {
        if (mS.atEnd()) return true;
        const char c = mS.peek();
        return c == ',' || c == ')' || c == ':' || mS.atArrow();
    }

    static int precedence(ExprOp op) {
        switch (op) {
        case ExprOp::Or:
            return 1;
        case ExprOp::And:
            return 2;
        case ExprOp::Eq:
        case ExprOp::Ne:
            return 3;
        case ExprOp::Lt:
        case ExprOp::Le:
        case ExprOp::Gt:
        case ExprOp::Ge:
            return 4;
        case ExprOp::Add:
        case ExprOp::Sub:
            return 5;
        case ExprOp::Mul:
        case ExprOp::Div:
            return 6;
        default:
            return 0;
        }
    }

    /// Reads a binary operator at the cursor without consuming it; width in chars.
    bool peekBinary(ExprOp& op, int& width) {
        if (atStop()) return false;
        const char c = mS.peek(), d = mS.peek(1);
        width = 1;
        switch (c) {
        case '+':
            op = ExprOp::Add;
            return true;
        case '-':
            op = ExprOp::Sub;
            return true;
        case '*':
            op = ExprOp::Mul;
            return true;
        case '/':
            op = ExprOp::Div;
            return true;
        case '<':
            if (d == '=') width = 2;
            op = d == '=' ? ExprOp::Le : ExprOp::Lt;
            return true;
        case '>':
            if (d == '=') width = 2;
            op = d == '=' ? ExprOp::Ge : ExprOp::Gt;
            return true;
        case '=':
            if (d != '=') return false;
            width = 2;
            op = ExprOp::Eq;
            return true;
        case '!':
            if (d != '=') return false;
            width = 2;
            op = ExprOp::Ne;
            return true;
        case '&':
            if (d != '&') return false;
            width = 2;
            op = ExprOp::And;
            return true;
        case '|':
            if (d != '|') return false;
            width = 2;
            op = ExprOp::Or;
            return true;
        default:
            return false;
        }
    }

    Code parseBinary(int minPrec) {
        Code lhs = parseUnary();
        for (;;) {
            ExprOp op;
            int width;
            if (!peekBinary(op, width)) break;
            const int prec = precedence(op);
            if (prec <= minPrec) break;
            const int column = mS.column();
            mS.advance(static_cast<std::size_t>(width));
            Code rhs = parseBinary(prec);
            lhs = combine(op, column, std::move(lhs), std::move(rhs));
        }
        if (minPrec == 0 && !atStop()) {
            mS.error("unexpected " + mS.describeHere() + " in expression");
            mS.setPosition(mS.text().size());
        }
        return lhs;
    }

    Code parseUnary() {
        mS.skipSpaces();
        const int column = mS.column();
        // Unary operators, '^', parentheses and call arguments all recurse through here: a
        // grammar line of 200,000 '(' overflowed the stack, so nesting is limited.
        if (mDepth >= kMaxExprNesting) {
            mS.error(column, "expression is nested too deeply (more than " +
                                 std::to_string(kMaxExprNesting) + " levels)");
            mS.setPosition(mS.text().size());
            mTooDeep = true;
            return constant(0.0, column);
        }
        ++mDepth;
        Code code = parseUnaryOperand(column);
        --mDepth;
        return code;
    }

    Code parseUnaryOperand(int column) {
        if (mS.peek() == '-' && mS.peek(1) != '>') {
            mS.advance();
            return combine(ExprOp::Neg, column, parseUnary(), {});
        }
        if (mS.peek() == '+') {
            mS.advance();
            return parseUnary();
        }
        if (mS.peek() == '!' && mS.peek(1) != '=') {
            mS.advance();
            return combine(ExprOp::Not, column, parseUnary(), {});
        }
        return parsePower();
    }

    Code parsePower() {
        Code base = parsePrimary();
        mS.skipSpaces();
        if (mS.peek() == '^') {
            const int column = mS.column();
            mS.advance();
            Code exponent = parseUnary(); // right-associative, binds tighter than unary minus
            return combine(ExprOp::Pow, column, std::move(base), std::move(exponent));
        }
        return base;
    }

    Code constant(double v, int column) { return Code{ExprInstr{ExprOp::Const, 0, column, v}}; }

    Code parsePrimary() {
        mS.skipSpaces();
        const int column = mS.column();
        const char c = mS.peek();
        if (atStop()) {
            mS.error("expected a number, a name or '(', found " + mS.describeHere());
            return constant(0.0, column);
        }
        if (c == '(') {
            mS.advance();
            const std::size_t errorsBefore = mS.errorCount();
            Code inner = parseBinary(0);
            if (!mS.consume(')') && mS.errorCount() == errorsBefore)
                mS.error("expected ')', found " + mS.describeHere());
            return inner;
        }
        if (isDigit(c) || (c == '.' && isDigit(mS.peek(1)))) {
            const std::string_view t = mS.text();
            std::size_t p = mS.position();
            while (p < t.size() && (isDigit(t[p]) || t[p] == '.'))
                ++p;
            if (p < t.size() && (t[p] == 'e' || t[p] == 'E')) {
                std::size_t q = p + 1;
                if (q < t.size() && (t[q] == '+' || t[q] == '-')) ++q;
                if (q < t.size() && isDigit(t[q])) {
                    p = q;
                    while (p < t.size() && isDigit(t[p]))
                        ++p;
                }
            }
            double v = 0.0;
            const auto r = std::from_chars(t.data() + mS.position(), t.data() + p, v);
            if (r.ec != std::errc() || r.ptr != t.data() + p) {
                mS.error("malformed number '" +
                         std::string(t.substr(mS.position(), p - mS.position())) + "'");
            }
            mS.setPosition(p);
            return constant(v, column);
        }
        if (isIdentStart(c)) {
            const std::string_view t = mS.text();
            std::size_t p = mS.position();
            while (p < t.size() && isIdentChar(t[p]))
                ++p;
            const std::string name(t.substr(mS.position(), p - mS.position()));
            mS.setPosition(p);
            mS.skipSpaces();
            if (mS.peek() == '(') return parseCall(name, column);
            if (mScope.formals) {
                for (std::size_t i = 0; i < mScope.formals->size(); ++i) {
                    if ((*mScope.formals)[i] == name)
                        return Code{
                            ExprInstr{ExprOp::Arg, static_cast<std::int32_t>(i), column, 0.0}};
                }
            }
            if (mScope.defines) {
                if (auto it = mScope.defines->find(name); it != mScope.defines->end())
                    return constant(it->second, column);
            }
            mS.error(column, "unknown constant '" + name + "'");
            return constant(0.0, column);
        }
        mS.error("unexpected " + mS.describeHere() + " in expression");
        mS.setPosition(mS.text().size());
        return constant(0.0, column);
    }

    Code parseCall(const std::string& name, int column) {
        const FunctionInfo* fn = nullptr;
        for (const FunctionInfo& f : kFunctions)
            if (name == f.name) fn = &f;
        mS.advance(); // '('
        std::vector<Code> args;
        if (!mS.consume(')')) {
            for (;;) {
                args.push_back(parseBinary(0));
                if (mS.consume(',')) continue;
                if (mS.consume(')')) break;
                mS.error("expected ',' or ')' in the arguments of '" + name + "', found " +
                         mS.describeHere());
                mS.setPosition(mS.text().size());
                return constant(0.0, column);
            }
        }
        if (!fn) {
            mS.error(column, "unknown function '" + name +
                                 "' (known: sin cos tan sqrt abs min max floor exp log rand)");
            return constant(0.0, column);
        }
        if (static_cast<int>(args.size()) != fn->arity) {
            mS.error(column, "'" + name + "' takes " + std::to_string(fn->arity) +
                                 (fn->arity == 1 ? " argument" : " arguments") + ", got " +
                                 std::to_string(args.size()));
            return constant(0.0, column);
        }
        if (fn->op == ExprOp::Rand) {
            if (!mScope.allowRand) {
                mS.error(column,
                         std::string("rand() is not allowed here: ") + mScope.randForbiddenReason);
                return constant(0.0, column);
            }
            Code code = std::move(args[0]);
            code.insert(code.end(), args[1].begin(), args[1].end());
            code.push_back(ExprInstr{ExprOp::Rand, 0, column, 0.0});
            return code;
        }
        if (fn->arity == 1) return combine(fn->op, column, std::move(args[0]), {});
        return combine(fn->op, column, std::move(args[0]), std::move(args[1]));
    }

    static bool isConst(const Code& c) { return c.size() == 1 && c[0].op == ExprOp::Const; }

    Code combine(ExprOp op, int column, Code a, Code b) {
        const bool binary = arityOf(op) == 2;
        if (isConst(a) && (!binary || isConst(b))) {
            if (mTooDeep) return constant(0.0, column); // one message for the whole expression
            double v = 0.0;
            if (!apply(op, a[0].value, binary ? b[0].value : 0.0, v)) {
                mS.error(column, "division by zero");
                v = 0.0;
            } else if (!std::isfinite(v)) {
                mS.error(column, "the expression's value is not a finite number");
                v = 0.0;
            }
            return constant(v, column);
        }
        if (binary) a.insert(a.end(), b.begin(), b.end());
        a.push_back(ExprInstr{op, 0, column, 0.0});
        return a;
    }

    Scanner& mS;
    const ExprScope& mScope;
    int mDepth = 0;        ///< parseUnary() levels on the C++ stack
    bool mTooDeep = false; ///< kMaxExprNesting was reached (reported once)
};

bool compileExpression(Scanner& scanner, const ExprScope& scope, Expression& out) {
    ExpressionCompiler compiler(scanner, scope);
    return compiler.run(out);
}

} // namespace sylva::lsys
