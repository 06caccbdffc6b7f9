// Rewriting throughput: the table-driven fast path against a naive std::string rewriter and
// against the general (parametric/context/stochastic) path, on the same grammar.
// Items = modules written over all generations.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"

using namespace sylva::lsys;

namespace {

constexpr int kGenerations = 9; // 5^9 F's, 4.9 M modules in the last generation

/// Modules written by n generations of F -> F[+F]F[-F]F from F.
std::size_t writtenModules(int n) {
    std::size_t total = 0, f = 1, other = 0;
    for (int i = 1; i <= n; ++i) {
        other += 6 * f;
        f *= 5;
        total += f + other;
    }
    return total;
}

DeriveOptions generations(int n) {
    DeriveOptions o;
    o.generations = n;
    return o;
}

void BM_DeriveFastPath(benchmark::State& state) {
    const Grammar g = parseGrammar("axiom: F\nF -> F[+F]F[-F]F\n");
    std::size_t size = 0;
    for (auto _ : state) {
        ModuleString s = derive(g, generations(kGenerations));
        size = s.size();
        benchmark::DoNotOptimize(s.symbols.data());
    }
    state.counters["final_modules"] = static_cast<double>(size);
    state.SetItemsProcessed(
        static_cast<std::int64_t>(state.iterations() * writtenModules(kGenerations)));
}

/// The naive version: one std::string concatenation and one std::map lookup per module.
void BM_DeriveNaive(benchmark::State& state) {
    const std::map<char, std::string> rules{{'F', "F[+F]F[-F]F"}};
    std::size_t size = 0;
    for (auto _ : state) {
        std::string word = "F";
        for (int i = 0; i < kGenerations; ++i) {
            std::string next;
            for (char c : word) {
                auto it = rules.find(c);
                next += it == rules.end() ? std::string(1, c) : it->second;
            }
            word = std::move(next);
        }
        size = word.size();
        benchmark::DoNotOptimize(word.data());
    }
    state.counters["final_modules"] = static_cast<double>(size);
    state.SetItemsProcessed(
        static_cast<std::int64_t>(state.iterations() * writtenModules(kGenerations)));
}

/// The same rule on the general path (a parametric bystander module disables the fast path).
void BM_DeriveGeneralPath(benchmark::State& state) {
    const Grammar g = parseGrammar("axiom: Z(0)F\nF -> F[+F]F[-F]F\nZ(x) -> Z(x + 1)\n");
    for (auto _ : state) {
        ModuleString s = derive(g, generations(kGenerations));
        benchmark::DoNotOptimize(s.symbols.data());
    }
    state.SetItemsProcessed(
        static_cast<std::int64_t>(state.iterations() * writtenModules(kGenerations)));
}

/// Context-sensitive, non-parametric: the acropetal signal grammar over a bracketed word.
void BM_DeriveContextSensitive(benchmark::State& state) {
    const Grammar g = parseGrammar("ignore: + -\naxiom: F\nF -> F[+F]F[-F]F\nb < F -> b\n");
    for (auto _ : state) {
        ModuleString s = derive(g, generations(kGenerations));
        benchmark::DoNotOptimize(s.symbols.data());
    }
    state.SetItemsProcessed(
        static_cast<std::int64_t>(state.iterations() * writtenModules(kGenerations)));
}

/// Parametric with conditions and expressions: every module carries two parameters.
void BM_DeriveParametric(benchmark::State& state) {
    const Grammar g = parseGrammar("define: r = 0.9\naxiom: A(1, 0.2)\n"
                                   "A(l, w) : l > 0.01 -> !(w)F(l)[&(30)A(l*r, w*0.7)]"
                                   "/(137.5)[&(30)A(l*r, w*0.7)]/(137.5)A(l*r, w*0.7)\n");
    std::size_t written = 0; // modules written over all 11 generations, counted untimed
    for (int n = 1; n <= 11; ++n)
        written += derive(g, generations(n)).size();
    for (auto _ : state) {
        ModuleString s = derive(g, generations(11));
        benchmark::DoNotOptimize(s.symbols.data());
    }
    state.counters["final_modules"] = static_cast<double>(derive(g, generations(11)).size());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * written));
}

/// Stochastic, non-parametric (ABOP fig. 1.27).
void BM_DeriveStochastic(benchmark::State& state) {
    const Grammar g = parseGrammar("axiom: F\nF -> F[+F]F[-F]F : 0.33\nF -> F[+F]F : 0.33\n"
                                   "F -> F[-F]F : 0.34\n");
    std::size_t size = 0;
    for (auto _ : state) {
        ModuleString s = derive(g, generations(12));
        size = s.size();
        benchmark::DoNotOptimize(s.symbols.data());
    }
    state.counters["final_modules"] = static_cast<double>(size);
}

void BM_ParseGrammar(benchmark::State& state) {
    const std::string text = "generations: 5\nangle: 22.5\ndefine: r1 = 0.9\naxiom: A(1, 0.1)\n"
                             "A(l,w) : l > 0.1 -> !(w)F(l)[&(45)B(l*r1)]/(137.5)A(l*r1, w*0.7)\n"
                             "B(l) -> F(l)[-B(l*r1)]B(l*r1)\n";
    for (auto _ : state)
        benchmark::DoNotOptimize(parseGrammar(text).rules.size());
}

} // namespace

BENCHMARK(BM_DeriveFastPath)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeriveNaive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeriveGeneralPath)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeriveContextSensitive)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeriveParametric)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeriveStochastic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseGrammar)->Unit(benchmark::kMicrosecond);
