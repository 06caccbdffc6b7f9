// Space colonization: the accelerated closest-node search against the naive O(points × nodes)
// oracle, in the same process, on the reference's round crown (sphere r 4.5, d_i 3, d_k 0.6,
// D 0.2, randomness 0.147). Accelerated runs report `speedup` = naive time / own time for the
// sizes where the naive version ran first (it takes minutes at 100k, so it stops at 30k).
//   bench_spacecolonization --benchmark_filter=...   (see docs/perf/spacecol.md)
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <omp.h>

#include "engine/growth/envelope.h"
#include "engine/growth/spacecolonization.h"

using namespace sylva::growth;

namespace {

std::map<int, double> gNaiveSeconds; // per point count, filled by the naive runs

const std::vector<glm::vec3>& points(int n) {
    static std::map<int, std::vector<glm::vec3>> cache;
    auto it = cache.find(n);
    if (it == cache.end())
        it = cache.emplace(n, Envelope::sphere({0, 6, 0}, 4.5f).sample(std::size_t(n), 7)).first;
    return it->second;
}

ColonizationParams params() {
    ColonizationParams p;
    p.trunkHeight = 2.0f;
    return p;
}

double run(benchmark::State& state, NeighbourSearch search) {
    const auto& pts = points(int(state.range(0)));
    double seconds = 0.0;
    std::size_t nodes = 0;
    int iterations = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        ColonizationResult r = colonize(pts, params(), nullptr, search);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        nodes = r.skeleton.size();
        iterations = r.iterations;
        benchmark::DoNotOptimize(r);
    }
    state.counters["nodes"] = double(nodes);
    state.counters["growth_steps"] = iterations;
    return seconds / double(state.iterations());
}

void BM_ColonizeNaive(benchmark::State& state) {
    gNaiveSeconds[int(state.range(0))] = run(state, NeighbourSearch::Naive);
}

void BM_ColonizeAccelerated(benchmark::State& state) {
    const int threads = int(state.range(1));
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    const double seconds = run(state, NeighbourSearch::Accelerated);
    omp_set_num_threads(saved);
    state.counters["threads"] = threads;
    const auto naive = gNaiveSeconds.find(int(state.range(0)));
    if (naive != gNaiveSeconds.end()) state.counters["speedup"] = naive->second / seconds;
}

void BM_SampleSphere(benchmark::State& state) {
    const Envelope e = Envelope::sphere({0, 6, 0}, 4.5f);
    for (auto _ : state)
        benchmark::DoNotOptimize(e.sample(std::size_t(state.range(0)), 7));
}

} // namespace

// The naive runs are registered first so that their times exist when the accelerated ones run.
BENCHMARK(BM_ColonizeNaive)
    ->Arg(3000)
    ->Arg(10000)
    ->Arg(30000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_ColonizeAccelerated)
    ->ArgsProduct({{3000, 10000, 30000, 100000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.3);
BENCHMARK(BM_SampleSphere)->Arg(100000)->Unit(benchmark::kMillisecond);
