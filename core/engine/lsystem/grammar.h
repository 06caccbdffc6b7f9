#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "engine/lsystem/expression.h"
#include "engine/util/error.h"

namespace sylva::lsys {

/// One module of a rule's predecessor or context: a symbol and its number of formal
/// parameters (the formals' names live in Rule::formals, in order of appearance).
struct PatternModule {
    char symbol = 0;
    std::uint8_t arity = 0;
};

/// A module to produce: its symbol and `argCount` expressions starting at `firstArg` in the
/// owning ModuleTemplate::args.
struct ModuleCall {
    char symbol = 0;
    std::uint8_t argCount = 0;
    std::uint32_t firstArg = 0;
};

/// A module list with parameter expressions: a successor or the axiom.
struct ModuleTemplate {
    std::vector<ModuleCall> modules;
    std::vector<Expression> args;
};

/// One production `left < predecessor > right : condition -> successor : weight`.
struct Rule {
    int line = 0;                    ///< 1-based line of the rule in its file
    int column = 0;                  ///< 1-based column of the predecessor
    std::string text;                ///< the rule's source text, for messages
    std::vector<PatternModule> left; ///< left context in string order (no brackets)
    PatternModule predecessor;
    std::vector<PatternModule> right; ///< right context; may hold '[' and ']'
    std::vector<std::string> formals; ///< slots: left formals, then predecessor's, then right's
    bool hasCondition = false;
    Expression condition;
    ModuleTemplate successor;
    bool weighted = false;
    double weight = 1.0;
};

/// Rules sharing their text before `->` (context, predecessor, condition). A group with one
/// unweighted rule is deterministic; otherwise one member is drawn by weight.
struct RuleGroup {
    std::vector<int> rules;         ///< indices into Grammar::rules, file order
    std::vector<double> cumulative; ///< running sums of the weights (last == 1 up to 1e-6)
    bool contextSensitive = false;
    bool stochastic = false;
};

/// A parsed grammar, ready to derive. Header values default as documented in docs/grammar.md.
struct Grammar {
    std::string fileName;
    int generations = 0;        ///< how many rewriting steps derive() applies, >= 0
    double angleDegrees = 90.0; ///< default angle of + - & ^ \ / (degrees)
    double step = 1.0;          ///< default length of F and f (metres)
    double width = 0.1;         ///< initial width, i.e. branch diameter (metres)
    double widthFactor = 0.7;   ///< what ! without a parameter multiplies the width by
    std::uint64_t seed = 0;     ///< seed of stochastic rules and rand()
    int axiomLine = 0;          ///< 1-based line of the axiom in its file

    // Internal representation (filled by parseGrammar, read by derive()).
    ModuleTemplate axiom;
    std::vector<Rule> rules;
    std::vector<RuleGroup> groups;
    /// Per symbol: indices into `groups`, context-sensitive groups first, each part in file order.
    std::array<std::vector<int>, 256> groupsBySymbol;
    std::array<bool, 256> ignored{}; ///< symbols transparent to context matching
    std::map<std::string, double> defines;
    bool parametric = false;       ///< some module anywhere carries parameters
    bool contextSensitive = false; ///< some rule has a context
    bool stochastic = false;       ///< some group is stochastic or some expression uses rand()
    bool conditional = false;      ///< some rule has a condition
    bool legacyFormat = false;     ///< parsed from the reference-000 plain format
};

/// Turtle symbols and the most parameters each takes; other symbols are user modules whose
/// arity must be the same at every use. Returns -1 for a non-turtle symbol.
int turtleMaxArity(char symbol);

/// Parses the Sylva grammar language (docs/grammar.md), or the legacy plain format of reference
/// 000 (detected when the first line that is not blank or a comment is a bare integer; its
/// angle is in radians and converted). Collects all diagnostics (file, line, column) and
/// throws sylva::InvalidInput with them if there is any.
Grammar parseGrammar(std::string_view text, const std::string& fileName = "");

/// What checkGrammar() found: every diagnostic (file, 1-based line and column, message) in
/// text order, and the grammar, usable only when there are none.
struct GrammarCheck {
    Grammar grammar;
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return diagnostics.empty(); }
};

/// Parses like parseGrammar() but never throws for a malformed grammar: errors are normal while
/// typing, so the editor lists them all (squiggles, a list) as the user types.
GrammarCheck checkGrammar(std::string_view text, const std::string& fileName = "");

} // namespace sylva::lsys
