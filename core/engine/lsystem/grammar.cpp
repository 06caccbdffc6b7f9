#include "engine/lsystem/grammar.h"

#include <charconv>
#include <cmath>
#include <numbers>

#include "engine/lsystem/scanner.h"
#include "engine/util/error.h"
#include "engine/util/text.h"

namespace sylva::lsys {

int turtleMaxArity(char symbol) {
    switch (symbol) {
    case 'F':
    case 'f':
    case '+':
    case '-':
    case '&':
    case '^':
    case '\\':
    case '/':
    case '!':
    case 'J':
        return 1;
    case '[':
    case ']':
    case '|':
    case '$':
    case '%':
        return 0;
    default:
        return -1;
    }
}

namespace {

constexpr double kWeightTolerance = 1e-6;
constexpr int kMaxGenerations = 1000;
constexpr std::size_t kMaxFormals = 64;

bool isIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
    return isIdentStart(c) || (c >= '0' && c <= '9');
}

/// Printable ASCII that is not a separator of the language and not a digit.
bool isModuleChar(char c) {
    if (c <= ' ' || c > '~') return false;
    if (c >= '0' && c <= '9') return false;
    switch (c) {
    case '(':
    case ')':
    case ',':
    case ':':
    case '<':
    case '>':
    case '#':
    case '=':
        return false;
    default:
        return true;
    }
}

std::string quoted(char c) {
    return std::string("'") + c + "'";
}

std::string removeSpaces(std::string_view s) {
    std::string out;
    for (char c : s)
        if (c != ' ' && c != '\t' && c != '\r') out += c;
    return out;
}

std::string trim(std::string_view s) {
    std::size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r'))
        ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r'))
        --b;
    return std::string(s.substr(a, b - a));
}

/// Text without its trailing comment.
std::string_view stripComment(std::string_view line) {
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

class GrammarParser {
public:
    GrammarParser(const std::string& fileName) : mFile(fileName) { mGrammar.fileName = fileName; }

    Grammar run(std::string_view text) {
        parse(text);
        if (!mDiagnostics.empty()) throw InvalidInput(std::move(mDiagnostics));
        mGrammar.axiomLine = mAxiomLine;
        return std::move(mGrammar);
    }

    /// Like run(), but hands every diagnostic back instead of throwing (the grammar is only
    /// usable when there is none).
    Grammar runCollecting(std::string_view text, std::vector<Diagnostic>& diagnostics) {
        parse(text);
        diagnostics = std::move(mDiagnostics);
        mGrammar.axiomLine = mAxiomLine;
        return std::move(mGrammar);
    }

private:
    void parse(std::string_view text) {
        std::vector<std::string_view> lines;
        std::size_t start = 0;
        while (start <= text.size()) {
            std::size_t end = text.find('\n', start);
            if (end == std::string_view::npos) end = text.size();
            lines.push_back(text.substr(start, end - start));
            start = end + 1;
        }
        mLegacy = detectLegacy(lines);
        mGrammar.legacyFormat = mLegacy;
        int legacyHeader = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const int lineNo = static_cast<int>(i) + 1;
            Scanner s(lines[i], lineNo, mFile, mDiagnostics);
            if (s.atEnd()) continue;
            if (!checkCharacters(s)) continue;
            if (mLegacy) {
                parseLegacyLine(s, legacyHeader);
            } else {
                parseLine(s);
            }
        }
        finish();
    }

    // ---- line level -------------------------------------------------------------------------

    static bool detectLegacy(const std::vector<std::string_view>& lines) {
        for (std::string_view line : lines) {
            const std::string t = trim(stripComment(line));
            if (t.empty()) continue;
            for (char c : t)
                if (c < '0' || c > '9') return false;
            return true;
        }
        return false;
    }

    bool checkCharacters(Scanner& s) {
        const std::string_view t = s.text();
        for (std::size_t i = 0; i < t.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(t[i]);
            if (c == '#') break;
            if ((c < 32 && c != '\t' && c != '\r') || c > 126) {
                s.error(s.columnAt(i),
                        "unexpected byte 0x" + hex(c) + " (grammars are plain ASCII text)");
                return false;
            }
        }
        return true;
    }

    static std::string hex(unsigned char c) {
        const char* digits = "0123456789ABCDEF";
        return std::string{digits[c >> 4], digits[c & 15]};
    }

    void parseLine(Scanner& s) {
        // A setting is `word:` where word is a known key; everything with `->` is a rule.
        s.skipSpaces();
        const std::size_t begin = s.position();
        std::size_t p = begin;
        const std::string_view t = s.text();
        while (p < t.size() && isIdentChar(t[p]))
            ++p;
        std::size_t q = p;
        while (q < t.size() && (t[q] == ' ' || t[q] == '\t'))
            ++q;
        const std::string word(t.substr(begin, p - begin));
        const bool hasArrow = stripComment(t).find("->") != std::string_view::npos;
        if (p > begin + 1 && q < t.size() && t[q] == ':') {
            if (isSettingKey(word)) {
                s.setPosition(q + 1);
                parseSetting(s, word, s.columnAt(begin));
                return;
            }
            if (!hasArrow) {
                s.error(s.columnAt(begin),
                        "unknown setting '" + word +
                            "' (known: generations angle step width width_factor seed ignore "
                            "define axiom)");
                return;
            }
        }
        if (!hasArrow) {
            s.error(s.columnAt(begin),
                    "expected a setting ('name: value') or a rule ('predecessor -> successor')");
            return;
        }
        parseRule(s);
    }

    static bool isSettingKey(const std::string& w) {
        return w == "generations" || w == "angle" || w == "step" || w == "width" ||
               w == "width_factor" || w == "seed" || w == "ignore" || w == "define" || w == "axiom";
    }

    bool firstTime(const std::string& key, Scanner& s, int column) {
        auto [it, inserted] = mSettingLines.emplace(key, s.line());
        if (!inserted) {
            s.error(column, "'" + key + "' is given twice (first at line " +
                                std::to_string(it->second) + ")");
            return false;
        }
        return true;
    }

    /// A constant value (defines allowed), which must end the line.
    bool constantValue(Scanner& s, double& value) {
        Expression e;
        ExprScope scope;
        scope.defines = &mGrammar.defines;
        scope.allowRand = false;
        scope.randForbiddenReason = "settings are constants";
        if (!compileExpression(s, scope, e)) return false;
        if (!s.atEnd()) {
            s.error("unexpected " + s.describeHere() + " after the value");
            return false;
        }
        value = e.constantValue();
        return true;
    }

    void parseSetting(Scanner& s, const std::string& key, int keyColumn) {
        if (key == "define") {
            parseDefine(s);
            return;
        }
        if (!firstTime(key, s, keyColumn)) return;
        s.skipSpaces();
        const int valueColumn = s.column();
        if (key == "axiom") {
            mAxiomLine = s.line();
            mAxiomColumn = keyColumn;
            ExprScope scope;
            scope.defines = &mGrammar.defines;
            const std::size_t errorsBefore = mDiagnostics.size();
            parseModuleList(s, scope, mGrammar.axiom, "axiom");
            if (!s.atEnd()) s.error("unexpected " + s.describeHere() + " in the axiom");
            if (mGrammar.axiom.modules.empty() && errorsBefore == mDiagnostics.size())
                s.error(keyColumn, "the axiom is empty");
            return;
        }
        if (key == "ignore") {
            while (!s.atEnd()) {
                const char c = s.peek();
                if (c == '[' || c == ']') {
                    s.error("brackets cannot be ignored: they give context matching its "
                            "branch structure");
                } else if (!isModuleChar(c)) {
                    s.error(quoted(c) + " is not a module symbol");
                } else {
                    mGrammar.ignored[static_cast<unsigned char>(c)] = true;
                }
                s.advance();
            }
            return;
        }
        if (key == "seed") {
            if (s.atEnd()) {
                s.error("expected a seed (a whole number >= 0)");
                return;
            }
            const std::string_view t = s.text().substr(s.position());
            std::uint64_t v = 0;
            const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
            s.advance(static_cast<std::size_t>(r.ptr - t.data()));
            if (r.ec != std::errc() || r.ptr == t.data() || !s.atEnd()) {
                s.error(valueColumn, "seed must be a whole number from 0 to 18446744073709551615");
                return;
            }
            mGrammar.seed = v;
            return;
        }
        double v = 0.0;
        if (s.atEnd()) {
            s.error("expected a value after '" + key + ":'");
            return;
        }
        if (!constantValue(s, v)) return;
        if (key == "generations") {
            if (v < 0 || v > kMaxGenerations || std::floor(v) != v) {
                s.error(valueColumn, "generations must be a whole number from 0 to " +
                                         std::to_string(kMaxGenerations));
                return;
            }
            mGrammar.generations = static_cast<int>(v);
        } else if (key == "angle") {
            mGrammar.angleDegrees = v;
        } else if (key == "step") {
            if (!(v > 0)) return s.error(valueColumn, "step must be > 0 (metres)");
            mGrammar.step = v;
        } else if (key == "width") {
            if (!(v >= 0)) return s.error(valueColumn, "width must be >= 0 (metres)");
            mGrammar.width = v;
        } else if (key == "width_factor") {
            if (!(v > 0)) return s.error(valueColumn, "width_factor must be > 0");
            mGrammar.widthFactor = v;
        }
    }

    void parseDefine(Scanner& s) {
        s.skipSpaces();
        const std::size_t begin = s.position();
        const std::string_view t = s.text();
        if (!isIdentStart(s.peek())) {
            s.error("expected a name after 'define:' (define: name = value)");
            return;
        }
        std::size_t p = begin;
        while (p < t.size() && isIdentChar(t[p]))
            ++p;
        const std::string name(t.substr(begin, p - begin));
        s.setPosition(p);
        if (!s.consume('=')) {
            s.error("expected '=' after '" + name + "', found " + s.describeHere());
            return;
        }
        double v = 0.0;
        if (s.atEnd()) {
            s.error("expected a value after '='");
            return;
        }
        if (!constantValue(s, v)) return;
        if (mGrammar.defines.count(name)) {
            s.error(s.columnAt(begin), "'" + name + "' is defined twice (first at line " +
                                           std::to_string(mDefineLines[name]) + ")");
            return;
        }
        mGrammar.defines[name] = v;
        mDefineLines[name] = s.line();
    }

    // ---- modules ----------------------------------------------------------------------------

    /// Records a use of \p c with \p arity; diagnoses inconsistent arities of user modules and
    /// too many parameters on turtle symbols.
    void checkArity(Scanner& s, char c, int arity, int column) {
        const int turtleMax = turtleMaxArity(c);
        if (turtleMax >= 0) {
            if (arity > turtleMax) {
                s.error(column, quoted(c) + " takes " +
                                    (turtleMax == 0 ? std::string("no parameters")
                                                    : "at most 1 parameter") +
                                    ", got " + std::to_string(arity));
            }
            return;
        }
        ArityUse& use = mArity[static_cast<unsigned char>(c)];
        if (use.line == 0) {
            use = {arity, s.line(), column};
        } else if (use.arity != arity) {
            s.error(column, "wrong parameter count: module " + quoted(c) + " has " +
                                std::to_string(arity) + " parameter" + (arity == 1 ? "" : "s") +
                                " here but " + std::to_string(use.arity) + " at line " +
                                std::to_string(use.line) + ":" + std::to_string(use.column));
        }
    }

    /// Parses modules with argument expressions until a `:` or the end of the line.
    void parseModuleList(Scanner& s, const ExprScope& scope, ModuleTemplate& out,
                         const char* what) {
        std::vector<int> open;
        while (!s.atEnd() && s.peek() != ':') {
            const int column = s.column();
            const char c = s.peek();
            if (!isModuleChar(c)) {
                s.error(quoted(c) + " cannot be a module in the " + what +
                        " (modules are letters and turtle symbols such as F f + - & ^ \\ / | [ "
                        "] ! $ % J)");
                s.setPosition(s.text().size());
                return;
            }
            s.advance();
            ModuleCall call;
            call.symbol = c;
            call.firstArg = static_cast<std::uint32_t>(out.args.size());
            s.skipSpaces();
            if (s.peek() == '(') {
                s.advance();
                if (s.consume(')')) {
                    s.error(column, "empty parameter list after " + quoted(c));
                } else {
                    for (;;) {
                        Expression e;
                        if (!compileExpression(s, scope, e)) {
                            s.setPosition(s.text().size());
                            return;
                        }
                        out.args.push_back(std::move(e));
                        if (s.consume(',')) continue;
                        if (s.consume(')')) break;
                        s.error("expected ',' or ')' in the parameters of " + quoted(c) +
                                ", found " + s.describeHere());
                        s.setPosition(s.text().size());
                        return;
                    }
                }
            }
            const std::size_t argc = out.args.size() - call.firstArg;
            if (argc > 255) {
                s.error(column, "a module has at most 255 parameters");
                return;
            }
            call.argCount = static_cast<std::uint8_t>(argc);
            if (c == '[') open.push_back(column);
            if (c == ']') {
                if (open.empty())
                    s.error(column,
                            std::string("unbalanced brackets: ']' without '[' in the ") + what);
                else
                    open.pop_back();
            }
            checkArity(s, c, call.argCount, column);
            if (call.argCount > 0) mGrammar.parametric = true;
            out.modules.push_back(call);
        }
        for (int column : open)
            s.error(column, std::string("unbalanced brackets: '[' is never closed in the ") + what);
    }

    /// Parses predecessor-side modules with formal names until `<` `>` `:` or the arrow.
    bool parsePatternList(Scanner& s, std::vector<PatternModule>& out, std::vector<int>& columns,
                          std::vector<std::string>& formals) {
        while (!s.atEnd() && !atArrowToken(s)) {
            const char c = s.peek();
            if (c == '<' || c == '>' || c == ':') break;
            const int column = s.column();
            if (!isModuleChar(c)) {
                s.error(quoted(c) + " cannot be a module (expected a predecessor like A or "
                                    "A(x, y))");
                return false;
            }
            s.advance();
            PatternModule m;
            m.symbol = c;
            s.skipSpaces();
            if (s.peek() == '(') {
                s.advance();
                int n = 0;
                for (;;) {
                    s.skipSpaces();
                    const std::size_t begin = s.position();
                    if (!isIdentStart(s.peek())) {
                        s.error("expected a parameter name in the predecessor, found " +
                                s.describeHere());
                        return false;
                    }
                    std::size_t p = begin;
                    const std::string_view t = s.text();
                    while (p < t.size() && isIdentChar(t[p]))
                        ++p;
                    std::string name(t.substr(begin, p - begin));
                    for (const std::string& f : formals) {
                        if (f == name) {
                            s.error(s.columnAt(begin),
                                    "parameter '" + name + "' appears twice in this rule");
                            return false;
                        }
                    }
                    formals.push_back(std::move(name));
                    ++n;
                    s.setPosition(p);
                    if (s.consume(',')) continue;
                    if (s.consume(')')) break;
                    s.error("expected ',' or ')' after a parameter name, found " +
                            s.describeHere());
                    return false;
                }
                if (n > 255) {
                    s.error(column, "a module has at most 255 parameters");
                    return false;
                }
                m.arity = static_cast<std::uint8_t>(n);
            }
            checkArity(s, c, m.arity, column);
            if (m.arity > 0) mGrammar.parametric = true;
            out.push_back(m);
            columns.push_back(column);
        }
        return true;
    }

    bool atArrowToken(Scanner& s) {
        if (mLegacy) {
            s.skipSpaces();
            return s.peek() == '=';
        }
        return s.atArrow();
    }

    // ---- rules ------------------------------------------------------------------------------

    void parseRule(Scanner& s) {
        const std::size_t errorsBefore = mDiagnostics.size();
        Rule rule;
        rule.line = s.line();
        rule.text = trim(stripComment(s.text()));
        s.skipSpaces();
        const std::size_t lhsBegin = s.position();

        std::vector<PatternModule> first;
        std::vector<int> firstColumns;
        if (!parsePatternList(s, first, firstColumns, rule.formals)) return;
        std::vector<int> predColumns = firstColumns;
        std::vector<PatternModule> pred = first;
        if (s.consume('<')) {
            const int ltColumn = s.column() - 1;
            if (first.empty()) {
                s.error(ltColumn, "expected a left context before '<'");
                return;
            }
            for (std::size_t i = 0; i < first.size(); ++i) {
                if (first[i].symbol == '[' || first[i].symbol == ']') {
                    s.error(firstColumns[i], "brackets are not allowed in a left context (it "
                                             "skips complete branches by itself)");
                    return;
                }
            }
            rule.left = first;
            pred.clear();
            predColumns.clear();
            if (!parsePatternList(s, pred, predColumns, rule.formals)) return;
        }
        if (pred.size() != 1) {
            const int column =
                predColumns.empty() ? s.column() : predColumns[1 % predColumns.size()];
            s.error(column, pred.empty() ? "expected a predecessor module"
                                         : "the predecessor must be a single module (use "
                                           "'left < pred > right' for context)");
            return;
        }
        rule.predecessor = pred[0];
        rule.column = predColumns[0];
        if (pred[0].symbol == '[' || pred[0].symbol == ']') {
            s.error(rule.column, "brackets cannot be rewritten");
            return;
        }
        if (s.consume('>')) {
            std::vector<int> columns;
            if (!parsePatternList(s, rule.right, columns, rule.formals)) return;
            if (rule.right.empty()) {
                s.error("expected a right context after '>'");
                return;
            }
        }
        if (rule.formals.size() > kMaxFormals) {
            s.error(rule.column, "a rule has at most " + std::to_string(kMaxFormals) +
                                     " parameters in its predecessor and context");
            return;
        }
        if (s.consume(':')) {
            s.skipSpaces();
            const std::size_t save = s.position();
            bool star = false;
            if (s.peek() == '*') {
                s.advance();
                if (atArrowToken(s))
                    star = true;
                else
                    s.setPosition(save);
            }
            if (!star) {
                ExprScope scope;
                scope.formals = &rule.formals;
                scope.defines = &mGrammar.defines;
                if (!compileExpression(s, scope, rule.condition)) return;
                rule.hasCondition = true;
                mGrammar.conditional = true;
            }
        }
        const std::size_t lhsEnd = s.position();
        if (!atArrowToken(s)) {
            s.error(std::string("expected '") + (mLegacy ? "=" : "->") + "', found " +
                    s.describeHere());
            return;
        }
        s.advance(mLegacy ? 1 : 2);
        ExprScope scope;
        scope.formals = &rule.formals;
        scope.defines = &mGrammar.defines;
        parseModuleList(s, scope, rule.successor, "successor");
        if (s.consume(':')) {
            s.skipSpaces();
            const int column = s.column();
            double w = 0;
            if (s.atEnd()) {
                s.error("expected a weight after ':'");
                return;
            }
            if (!constantValue(s, w)) return;
            if (!(w > 0.0 && w <= 1.0 + kWeightTolerance)) {
                s.error(column, "a weight must be in (0, 1], got " + formatNumber(w));
                return;
            }
            rule.weighted = true;
            rule.weight = w;
        } else if (!s.atEnd()) {
            s.error("unexpected " + s.describeHere() + " in the successor");
        }
        if (mDiagnostics.size() != errorsBefore) return;
        mKeys.push_back(removeSpaces(s.text().substr(lhsBegin, lhsEnd - lhsBegin)));
        mGrammar.rules.push_back(std::move(rule));
    }

    static std::string formatNumber(double v) { return shortestDecimal(v); }

    // ---- legacy format ----------------------------------------------------------------------

    void parseLegacyLine(Scanner& s, int& header) {
        s.skipSpaces();
        const int column = s.column();
        switch (header) {
        case 0: {
            double v = 0;
            if (constantValue(s, v)) {
                if (v < 0 || v > kMaxGenerations || std::floor(v) != v)
                    s.error(column, "generations must be a whole number from 0 to " +
                                        std::to_string(kMaxGenerations));
                else
                    mGrammar.generations = static_cast<int>(v);
            }
            ++header;
            return;
        }
        case 1: {
            double v = 0;
            if (constantValue(s, v)) mGrammar.angleDegrees = v * 180.0 / std::numbers::pi;
            ++header;
            return;
        }
        case 2: {
            double v = 0;
            if (constantValue(s, v)) {
                if (!(v >= 0))
                    s.error(column, "thickness must be >= 0");
                else
                    mGrammar.width = v;
            }
            ++header;
            return;
        }
        case 3: {
            mAxiomLine = s.line();
            mAxiomColumn = column;
            ExprScope scope;
            parseModuleList(s, scope, mGrammar.axiom, "axiom");
            if (!s.atEnd()) s.error("unexpected " + s.describeHere() + " in the axiom");
            ++header;
            return;
        }
        default:
            if (stripComment(s.text()).find('=') == std::string_view::npos) {
                s.error(column, "expected a rule 'Rule = Replacement : Probability'");
                return;
            }
            parseRule(s);
        }
    }

    // ---- whole grammar ----------------------------------------------------------------------

    void finish() {
        if (mAxiomLine == 0) {
            mDiagnostics.push_back(
                {mFile, 0, 0,
                 mLegacy ? "no axiom: the fourth line of a legacy grammar is the axiom"
                         : "no axiom: add a line 'axiom: ...'"});
        }
        // Groups: rules with identical text before the arrow.
        std::map<std::string, int> groupOf;
        for (std::size_t i = 0; i < mGrammar.rules.size(); ++i) {
            const Rule& r = mGrammar.rules[i];
            auto [it, inserted] =
                groupOf.emplace(mKeys[i], static_cast<int>(mGrammar.groups.size()));
            if (inserted) {
                RuleGroup g;
                g.contextSensitive = !r.left.empty() || !r.right.empty();
                mGrammar.groups.push_back(g);
            }
            mGrammar.groups[static_cast<std::size_t>(it->second)].rules.push_back(
                static_cast<int>(i));
        }
        for (RuleGroup& g : mGrammar.groups) {
            const Rule& head = mGrammar.rules[static_cast<std::size_t>(g.rules[0])];
            bool anyWeighted = false, anyUnweighted = false;
            double sum = 0;
            for (int ri : g.rules) {
                const Rule& r = mGrammar.rules[static_cast<std::size_t>(ri)];
                (r.weighted ? anyWeighted : anyUnweighted) = true;
                sum += r.weight;
                g.cumulative.push_back(sum);
            }
            if (anyUnweighted && g.rules.size() > 1) {
                for (std::size_t k = 1; k < g.rules.size(); ++k) {
                    const Rule& r = mGrammar.rules[static_cast<std::size_t>(g.rules[k])];
                    mDiagnostics.push_back(
                        {mFile, r.line, r.column,
                         "this rule has the same predecessor, context and condition as the rule "
                         "at line " +
                             std::to_string(head.line) +
                             "; give every alternative a weight (': 0.5') to make them "
                             "stochastic"});
                }
                continue;
            }
            if (anyWeighted && std::fabs(sum - 1.0) > kWeightTolerance) {
                std::string lines;
                for (int ri : g.rules) {
                    if (!lines.empty()) lines += ", ";
                    lines += std::to_string(mGrammar.rules[static_cast<std::size_t>(ri)].line);
                }
                mDiagnostics.push_back({mFile, head.line, head.column,
                                        "the weights of the rules for " +
                                            quoted(head.predecessor.symbol) + " (line" +
                                            (g.rules.size() > 1 ? "s " : " ") + lines +
                                            ") sum to " + formatNumber(sum) + ", not 1"});
                continue;
            }
            // Normalise so the last cumulative weight is exactly 1 and every draw picks a rule.
            for (double& c : g.cumulative)
                c /= sum;
            g.cumulative.back() = 1.0;
            g.stochastic = g.rules.size() > 1;
            if (g.stochastic) mGrammar.stochastic = true;
            if (g.contextSensitive) mGrammar.contextSensitive = true;
        }
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t gi = 0; gi < mGrammar.groups.size(); ++gi) {
                const RuleGroup& g = mGrammar.groups[gi];
                if (g.contextSensitive != (pass == 0)) continue;
                const char sym =
                    mGrammar.rules[static_cast<std::size_t>(g.rules[0])].predecessor.symbol;
                mGrammar.groupsBySymbol[static_cast<unsigned char>(sym)].push_back(
                    static_cast<int>(gi));
            }
        }
        auto usesRand = [](const ModuleTemplate& t) {
            for (const Expression& e : t.args)
                if (e.usesRand()) return true;
            return false;
        };
        if (usesRand(mGrammar.axiom)) mGrammar.stochastic = true;
        for (const Rule& r : mGrammar.rules) {
            if (usesRand(r.successor) || (r.hasCondition && r.condition.usesRand()))
                mGrammar.stochastic = true;
        }
    }

    struct ArityUse {
        int arity = 0;
        int line = 0;
        int column = 0;
    };

    std::string mFile;
    Grammar mGrammar;
    std::vector<Diagnostic> mDiagnostics;
    std::vector<std::string> mKeys; ///< per rule: its text before the arrow, spaces removed
    std::map<std::string, int> mSettingLines;
    std::map<std::string, int> mDefineLines;
    std::array<ArityUse, 256> mArity{};
    int mAxiomLine = 0;
    int mAxiomColumn = 0;
    bool mLegacy = false;
};

} // namespace

Grammar parseGrammar(std::string_view text, const std::string& fileName) {
    GrammarParser parser(fileName);
    return parser.run(text);
}

GrammarCheck checkGrammar(std::string_view text, const std::string& fileName) {
    GrammarCheck check;
    GrammarParser parser(fileName);
    check.grammar = parser.runCollecting(text, check.diagnostics);
    return check;
}

} // namespace sylva::lsys
