#include "engine/lsystem/derivation.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::lsys {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
constexpr std::size_t kCancelCheckInterval = 1u << 20;

/// Seed of generation \p gen's stream (0 is the axiom); per generation so that deriving
/// n and n+1 generations agree on the first n.
Rng generationRng(std::uint64_t seed, int gen) {
    return Rng(mixSeed(seed, static_cast<std::uint64_t>(gen)));
}

[[noreturn]] void throwLimit(int gen, std::size_t limit, std::size_t predicted) {
    std::string msg = "generation " + std::to_string(gen) + " would hold ";
    msg += predicted == kNone ? std::string("more than ") + std::to_string(limit)
                              : std::to_string(predicted);
    msg += " modules, more than the symbol limit of " + std::to_string(limit) +
           "; derive fewer generations or raise the limit (the lsystem node's symbol_limit, "
           "sylva-cli expand --limit; at most 2000000000)";
    throw LimitExceeded(msg);
}

/// Wall-clock budget of one derivation, checked where cancellation is.
class Deadline {
public:
    explicit Deadline(double seconds)
        : mSeconds(seconds), mEnd(std::chrono::steady_clock::now() +
                                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(seconds))) {}
    void check(int gen) const {
        if (std::chrono::steady_clock::now() <= mEnd) return;
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", mSeconds);
        throw LimitExceeded(
            "the derivation took more than its time limit of " + std::string(seconds) +
            " s (stopped in generation " + std::to_string(gen) +
            "); derive fewer generations or raise the limit (the lsystem node's time_limit, "
            "sylva-cli expand --time-limit; at most 86400 s)");
    }

private:
    double mSeconds;
    std::chrono::steady_clock::time_point mEnd;
};

[[noreturn]] void throwParamLimit(int gen, std::size_t symbolLimit) {
    throw LimitExceeded("generation " + std::to_string(gen) + " would hold more than " +
                        std::to_string(paramLimitOf(symbolLimit)) +
                        " module parameters, twice the symbol limit of " +
                        std::to_string(symbolLimit) +
                        "; derive fewer generations or raise the limit (the lsystem node's "
                        "symbol_limit, sylva-cli expand --limit; at most 2000000000)");
}

[[noreturn]] void throwEval(const Grammar& g, const Expression& e, const ExprError& err,
                            const Rule* rule, int gen) {
    std::string msg = err.kind == ExprError::DivisionByZero ? "division by zero"
                                                            : "a value that is not a finite number";
    if (rule)
        msg += " in the rule '" + rule->text + "' (line " + std::to_string(rule->line) + ")";
    else
        msg += " in the axiom";
    msg += " at generation " + std::to_string(gen);
    throw InvalidInput(std::vector<Diagnostic>{{g.fileName, e.line(), err.column, msg}});
}

std::uint64_t saturatingMulAdd(std::uint64_t acc, std::uint64_t a, std::uint64_t b) {
    std::uint64_t prod = 0, sum = 0;
    if (__builtin_mul_overflow(a, b, &prod) || __builtin_add_overflow(acc, prod, &sum))
        return std::numeric_limits<std::uint64_t>::max();
    return sum;
}

// ---- fast path: context-free, deterministic, no parameters ---------------------------------

bool fastPathApplies(const Grammar& g) {
    return !g.parametric && !g.contextSensitive && !g.stochastic && !g.conditional;
}

void deriveFast(const Grammar& g, ModuleString& cur, int generations, std::size_t limit,
                const Deadline& deadline, Progress& progress) {
    struct Entry {
        std::uint32_t offset;
        std::uint32_t length;
    };
    Entry table[256];
    std::string successors;
    std::size_t maxLength = 0;
    // Composition matrix: how many of each symbol one symbol's successor holds. It predicts the
    // next generation's histogram, hence its exact length, without touching the string.
    std::vector<std::pair<unsigned, std::uint32_t>> composition[256];
    for (int c = 0; c < 256; ++c) {
        const auto& groups = g.groupsBySymbol[static_cast<std::size_t>(c)];
        std::string succ;
        if (groups.empty()) {
            succ.assign(1, static_cast<char>(c));
        } else {
            const Rule& r = g.rules[static_cast<std::size_t>(
                g.groups[static_cast<std::size_t>(groups[0])].rules[0])];
            for (const ModuleCall& m : r.successor.modules)
                succ += m.symbol;
        }
        table[c] = {static_cast<std::uint32_t>(successors.size()),
                    static_cast<std::uint32_t>(succ.size())};
        maxLength = std::max(maxLength, succ.size());
        std::uint32_t counts[256] = {};
        for (char s : succ)
            ++counts[static_cast<unsigned char>(s)];
        for (unsigned d = 0; d < 256; ++d)
            if (counts[d]) composition[c].push_back({d, counts[d]});
        successors += succ;
    }
    successors.append(64, '\0'); // fixed-size copies may read past the last successor

    std::uint64_t histogram[256] = {};
    for (char c : cur.symbols)
        ++histogram[static_cast<unsigned char>(c)];

    std::string next;
    for (int gen = 1; gen <= generations; ++gen) {
        progress.checkCancelled();
        deadline.check(gen);
        std::uint64_t nextHistogram[256] = {};
        for (unsigned c = 0; c < 256; ++c) {
            if (!histogram[c]) continue;
            for (const auto& [d, n] : composition[c])
                nextHistogram[d] = saturatingMulAdd(nextHistogram[d], histogram[c], n);
        }
        std::uint64_t length = 0;
        for (unsigned c = 0; c < 256; ++c)
            length = saturatingMulAdd(length, nextHistogram[c], 1);
        if (length > limit) throwLimit(gen, limit, static_cast<std::size_t>(length));

        next.resize(static_cast<std::size_t>(length) + 64);
        char* dst = next.data();
        const char* src = successors.data();
        const auto* in = reinterpret_cast<const unsigned char*>(cur.symbols.data());
        const std::size_t n = cur.symbols.size();
        if (maxLength <= 16) {
            for (std::size_t i = 0; i < n; ++i) {
                const Entry e = table[in[i]];
                std::memcpy(dst, src + e.offset, 16);
                dst += e.length;
            }
        } else if (maxLength <= 32) {
            for (std::size_t i = 0; i < n; ++i) {
                const Entry e = table[in[i]];
                std::memcpy(dst, src + e.offset, 32);
                dst += e.length;
            }
        } else {
            for (std::size_t i = 0; i < n; ++i) {
                const Entry e = table[in[i]];
                std::memcpy(dst, src + e.offset, e.length);
                dst += e.length;
            }
        }
        next.resize(static_cast<std::size_t>(length));
        cur.symbols.swap(next);
        std::memcpy(histogram, nextHistogram, sizeof histogram);
        progress.report(static_cast<double>(gen) / generations, "expand");
    }
}

// ---- general path ---------------------------------------------------------------------------

/// Per group: where each pattern module's parameters go in the rule's slot array.
struct GroupInfo {
    const RuleGroup* group = nullptr;
    const Rule* head = nullptr;
    std::vector<int> leftBase;
    int predBase = 0;
    std::vector<int> rightBase;
};

class Deriver {
public:
    Deriver(const Grammar& g, std::size_t limit, const Deadline& deadline, Progress& progress,
            bool trace)
        : mG(g), mLimit(limit), mParamLimit(paramLimitOf(limit)), mDeadline(deadline),
          mProgress(progress), mTrace(trace) {
        mInfo.resize(g.groups.size());
        for (std::size_t i = 0; i < g.groups.size(); ++i) {
            GroupInfo& info = mInfo[i];
            info.group = &g.groups[i];
            info.head = &g.rules[static_cast<std::size_t>(g.groups[i].rules[0])];
            int slot = 0;
            for (const PatternModule& m : info.head->left) {
                info.leftBase.push_back(slot);
                slot += m.arity;
            }
            info.predBase = slot;
            slot += info.head->predecessor.arity;
            for (const PatternModule& m : info.head->right) {
                info.rightBase.push_back(slot);
                slot += m.arity;
            }
        }
        // Largest number of modules one module can become (1 when it may stay unchanged).
        for (int c = 0; c < 256; ++c) {
            std::size_t m = 1;
            for (int gi : g.groupsBySymbol[static_cast<std::size_t>(c)])
                for (int ri : g.groups[static_cast<std::size_t>(gi)].rules)
                    m = std::max(m, g.rules[static_cast<std::size_t>(ri)].successor.modules.size());
            mMaxLength[c] = m;
        }
    }

    void axiom(ModuleString& out, std::uint64_t seed) {
        Rng rng = generationRng(seed, 0);
        if (mG.axiom.modules.size() > mLimit) throwLimit(0, mLimit, mG.axiom.modules.size());
        append(out, mG.axiom, nullptr, nullptr, rng, 0);
        if (mTrace) out.origins.assign(out.symbols.size(), mG.axiomLine);
    }

    void generation(const ModuleString& cur, ModuleString& out, std::uint64_t seed, int gen) {
        mCur = &cur;
        mSym = cur.symbols.data();
        mN = cur.symbols.size();
        Rng rng = generationRng(seed, gen);
        mGen = gen;
        const bool parametric = mG.parametric;
        if (parametric) {
            mOffsets.resize(mN + 1);
            std::size_t o = 0;
            for (std::size_t i = 0; i < mN; ++i) {
                mOffsets[i] = o;
                o += cur.paramCounts[i];
            }
            mOffsets[mN] = o;
        }
        if (mG.contextSensitive) computePartners();

        std::uint64_t bound = 0;
        for (std::size_t i = 0; i < mN; ++i)
            bound += mMaxLength[static_cast<unsigned char>(mSym[i])];
        const std::size_t reserve =
            static_cast<std::size_t>(std::min<std::uint64_t>(bound, mLimit));
        out.clear();
        out.symbols.reserve(reserve);
        if (parametric) out.paramCounts.reserve(reserve);

        double slots[64];
        for (std::size_t i = 0; i < mN; ++i) {
            if ((i & (kCancelCheckInterval - 1)) == 0) {
                mProgress.checkCancelled();
                mDeadline.check(gen);
            }
            const unsigned char c = static_cast<unsigned char>(mSym[i]);
            const auto& groups = mG.groupsBySymbol[c];
            const int arity = parametric ? cur.paramCounts[i] : 0;
            bool applied = false;
            for (int gi : groups) {
                const GroupInfo& info = mInfo[static_cast<std::size_t>(gi)];
                const Rule& head = *info.head;
                if (head.predecessor.arity != arity) continue;
                if (!head.left.empty() && !matchLeft(i, info, slots)) continue;
                if (arity) bind(i, info.predBase, slots);
                if (!head.right.empty() && !matchRight(i + 1, 0, info, slots)) continue;
                if (head.hasCondition) {
                    double v = 0;
                    ExprError err;
                    if (!head.condition.evaluate(slots, rng, v, err))
                        throwEval(mG, head.condition, err, &head, gen);
                    if (v == 0.0) continue;
                }
                const Rule* rule = &head;
                if (info.group->stochastic) {
                    const double u = rng.uniform();
                    const auto& cum = info.group->cumulative;
                    std::size_t k = 0;
                    while (k + 1 < cum.size() && u >= cum[k])
                        ++k;
                    rule = &mG.rules[static_cast<std::size_t>(info.group->rules[k])];
                }
                append(out, rule->successor, rule, slots, rng, gen);
                if (mTrace) out.origins.resize(out.symbols.size(), rule->line);
                applied = true;
                break;
            }
            if (!applied) {
                out.symbols.push_back(static_cast<char>(c));
                if (mTrace) out.origins.push_back(cur.origins[i]);
                if (parametric) {
                    out.paramCounts.push_back(static_cast<std::uint8_t>(arity));
                    out.params.insert(out.params.end(),
                                      cur.params.begin() + static_cast<std::ptrdiff_t>(mOffsets[i]),
                                      cur.params.begin() +
                                          static_cast<std::ptrdiff_t>(mOffsets[i] + arity));
                    if (out.params.size() > mParamLimit) throwParamLimit(gen, mLimit);
                }
                if (out.symbols.size() > mLimit) throwLimit(gen, mLimit, kNone);
            }
        }
    }

private:
    void bind(std::size_t pos, int base, double* slots) const {
        const std::size_t n = mCur->paramCounts[pos];
        const double* p = mCur->params.data() + mOffsets[pos];
        for (std::size_t k = 0; k < n; ++k)
            slots[base + static_cast<int>(k)] = p[k];
    }

    int arityAt(std::size_t pos) const { return mG.parametric ? mCur->paramCounts[pos] : 0; }

    void computePartners() {
        mPartner.assign(mN, kNone);
        mStack.clear();
        for (std::size_t i = 0; i < mN; ++i) {
            if (mSym[i] == '[') {
                mStack.push_back(i);
            } else if (mSym[i] == ']' && !mStack.empty()) {
                mPartner[i] = mStack.back();
                mPartner[mStack.back()] = i;
                mStack.pop_back();
            }
        }
    }

    bool ignored(char c) const { return mG.ignored[static_cast<unsigned char>(c)]; }

    /// Left context: walks towards the root, skipping complete branches and ignored symbols.
    bool matchLeft(std::size_t i, const GroupInfo& info, double* slots) const {
        const auto& left = info.head->left;
        std::size_t j = i; // one past the candidate
        for (std::size_t k = left.size(); k-- > 0;) {
            const char want = left[k].symbol;
            for (;;) {
                if (j == 0) return false;
                const char c = mSym[j - 1];
                if (c == ']') {
                    const std::size_t open = mPartner[j - 1];
                    if (open == kNone) return false;
                    j = open;
                    continue;
                }
                if (c == '[' || (ignored(c) && c != want)) {
                    --j;
                    continue;
                }
                break;
            }
            --j;
            if (mSym[j] != want || arityAt(j) != left[k].arity) return false;
            if (left[k].arity) bind(j, info.leftBase[k], slots);
        }
        return true;
    }

    /// Right context from string position \p j and pattern index \p k: plain modules skip
    /// lateral branches along the axis; '[' in the pattern descends into a branch (any of the
    /// sibling branches at that point); ']' skips the rest of the current branch.
    bool matchRight(std::size_t j, std::size_t k, const GroupInfo& info, double* slots) const {
        const auto& right = info.head->right;
        if (k == right.size()) return true;
        const char want = right[k].symbol;
        if (want == ']') {
            while (j < mN) {
                const char c = mSym[j];
                if (c == '[') {
                    if (mPartner[j] == kNone) return false;
                    j = mPartner[j] + 1;
                    continue;
                }
                if (c == ']') return matchRight(j + 1, k + 1, info, slots);
                ++j;
            }
            return false;
        }
        if (want == '[') {
            for (;;) {
                while (j < mN && mSym[j] != '[' && mSym[j] != ']' && ignored(mSym[j]))
                    ++j;
                if (j >= mN || mSym[j] != '[') return false;
                if (matchRight(j + 1, k + 1, info, slots)) return true;
                if (mPartner[j] == kNone) return false;
                j = mPartner[j] + 1;
            }
        }
        for (;;) {
            if (j >= mN) return false;
            const char c = mSym[j];
            if (c == '[') {
                if (mPartner[j] == kNone) return false;
                j = mPartner[j] + 1;
                continue;
            }
            if (c == ']') return false;
            if (ignored(c) && c != want) {
                ++j;
                continue;
            }
            break;
        }
        if (mSym[j] != want || arityAt(j) != right[k].arity) return false;
        if (right[k].arity) bind(j, info.rightBase[k], slots);
        return matchRight(j + 1, k + 1, info, slots);
    }

    void append(ModuleString& out, const ModuleTemplate& t, const Rule* rule, const double* slots,
                Rng& rng, int gen) {
        if (out.symbols.size() + t.modules.size() > mLimit) throwLimit(gen, mLimit, kNone);
        for (const ModuleCall& m : t.modules) {
            out.symbols.push_back(m.symbol);
            if (!mG.parametric) continue;
            out.paramCounts.push_back(m.argCount);
            for (std::uint32_t a = 0; a < m.argCount; ++a) {
                const Expression& e = t.args[m.firstArg + a];
                double v = 0;
                ExprError err;
                if (!e.evaluate(slots, rng, v, err)) throwEval(mG, e, err, rule, gen);
                out.params.push_back(v);
            }
            if (out.params.size() > mParamLimit) throwParamLimit(gen, mLimit);
        }
    }

    const Grammar& mG;
    std::size_t mLimit;
    std::size_t mParamLimit;
    const Deadline& mDeadline;
    Progress& mProgress;
    bool mTrace;
    std::vector<GroupInfo> mInfo;
    std::size_t mMaxLength[256] = {};
    const ModuleString* mCur = nullptr;
    const char* mSym = nullptr;
    std::size_t mN = 0;
    int mGen = 0;
    std::vector<std::size_t> mOffsets;
    std::vector<std::size_t> mPartner;
    std::vector<std::size_t> mStack;
};

} // namespace

ModuleString derive(const Grammar& g, const DeriveOptions& opt, Progress& p) {
    const int generations = opt.generations.value_or(g.generations);
    if (generations < 0)
        throw InvalidInput("generations must be >= 0, got " + std::to_string(generations));
    const std::uint64_t seed = opt.seed.value_or(g.seed);
    if (!(opt.timeLimitSeconds > 0.0 && opt.timeLimitSeconds <= kMaxDeriveTimeLimit))
        throw InvalidInput("the derivation's time limit must be in (0, 86400] seconds, got " +
                           std::to_string(opt.timeLimitSeconds));
    const Deadline deadline(opt.timeLimitSeconds);
    Deriver deriver(g, opt.symbolLimit, deadline, p, opt.traceRules);
    ModuleString cur;
    deriver.axiom(cur, seed);
    if (fastPathApplies(g) && !opt.traceRules) {
        deriveFast(g, cur, generations, opt.symbolLimit, deadline, p);
        return cur;
    }
    ModuleString next;
    for (int gen = 1; gen <= generations; ++gen) {
        p.checkCancelled();
        deadline.check(gen);
        deriver.generation(cur, next, seed, gen);
        std::swap(cur, next);
        p.report(static_cast<double>(gen) / generations, "expand");
    }
    if (cur.params.empty()) cur.paramCounts.clear();
    return cur;
}

std::string formatModules(const ModuleString& s) {
    std::string out;
    out.reserve(s.symbols.size() + s.params.size() * 4);
    std::size_t p = 0;
    char buf[32];
    for (std::size_t i = 0; i < s.symbols.size(); ++i) {
        out += s.symbols[i];
        const std::size_t n = s.hasParams() ? s.paramCounts[i] : 0;
        if (n == 0) continue;
        out += '(';
        for (std::size_t k = 0; k < n; ++k) {
            if (k) out += ',';
            const auto r = std::to_chars(buf, buf + sizeof buf, s.params[p++]);
            out.append(buf, r.ptr);
        }
        out += ')';
    }
    return out;
}

} // namespace sylva::lsys
