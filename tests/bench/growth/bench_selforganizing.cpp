// Self-organizing trees: one cycle of a ~100k-internode tree, a ~500k-internode tree, a
// 30-tree stand, each with incremental updates against the naive full recomputation.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include <omp.h>

#include "engine/growth/allocation.h"
#include "engine/growth/selforganizing.h"

using namespace sylva::growth;

namespace {

/// A vigorous shadow-propagation tree (conifer-like preset with α = 4) that reaches 10^5
/// internodes in about 20 cycles.
SelfOrganizingParams benchParams() {
    SelfOrganizingParams p;
    p.environment = SoEnvironment::ShadowPropagation;
    p.cycles = 200;
    p.alpha = 4.0;
    p.lambda = 0.5;
    p.shadowA = 0.2;
    p.internodeLength = 0.25;
    p.branchAngle = 85;
    p.optimalWeight = 0.05;
    p.tropismWeight = 0.5;
    p.lateralTropismWeight = -0.03;
    p.sheddingThreshold = 0.1;
    p.leafSize = 0.0;
    p.maxInternodes = 5'000'000;
    return p;
}

/// The shipped conifer preset (presets/so-conifer.json) without leaves: a tree that adds about
/// 30 % and sheds about 15 % of its size per cycle at 100k internodes (the bench tree above
/// replaces ~90 %).
SelfOrganizingParams coniferParams() {
    SelfOrganizingParams p = benchParams();
    p.alpha = 2.0;
    p.lambda = 0.55;
    p.sheddingThreshold = 0.25;
    return p;
}

void growTo(SelfOrganizingSimulation& sim, std::size_t internodes) {
    while (sim.metamers().size() < internodes && !sim.done())
        sim.step();
}

/// One cycle of a tree that already has ~110k internodes: bud light, gathering, shedding
/// (~40k metamers), Borchert–Honda, shoots (~60k new metamers) and the shadow update. Each
/// iteration grows a fresh simulation to that size (not timed) and times its next step(): a
/// copy of a grown simulation would time artefacts of the copy instead (vectors without spare
/// capacity reallocate on the first append; the copied grid loses its huge pages).
/// Arg 0: incremental shadow + linear allocation; 1: naive shadow + naive allocation.
/// Counters: the stages of the cycle in ms (mean over the iterations).
void runCycle100k(benchmark::State& state, const SelfOrganizingParams& params) {
    const bool naive = state.range(0) != 0;
    CycleTimings sum;
    std::vector<double> totals; // per iteration, for the median (this VM's speed drifts)
    std::size_t added = 0, shed = 0, before = 0;
    for (auto _ : state) {
        state.PauseTiming();
        SelfOrganizingSimulation sim({{glm::vec3(0), params, 1}}, {});
        growTo(sim, 100'000);
        sim.setOptions({naive, naive});
        before = sim.metamers().size();
        const std::size_t shedBefore = sim.shedCount();
        state.ResumeTiming();
        sim.step();
        state.PauseTiming();
        const CycleTimings& t = sim.lastTimings();
        sum.light += t.light;
        sum.shedding += t.shedding;
        sum.allocation += t.allocation;
        sum.shoots += t.shoots;
        sum.directions += t.directions;
        sum.making += t.making;
        sum.commit += t.commit;
        sum.environment += t.environment;
        totals.push_back(t.total);
        shed = sim.shedCount() - shedBefore;
        added = sim.metamers().size() + shed - before;
        state.ResumeTiming();
    }
    const auto n = static_cast<double>(state.iterations());
    state.counters["internodes"] = static_cast<double>(before);
    state.counters["new"] = static_cast<double>(added);
    state.counters["shed"] = static_cast<double>(shed);
    state.counters["light_ms"] = sum.light / n;
    state.counters["shedding_ms"] = sum.shedding / n;
    state.counters["alloc_ms"] = sum.allocation / n;
    state.counters["shoots_ms"] = sum.shoots / n;
    state.counters["dir_ms"] = sum.directions / n;
    state.counters["make_ms"] = sum.making / n;
    state.counters["commit_ms"] = sum.commit / n;
    state.counters["shadow_ms"] = sum.environment / n;
    std::sort(totals.begin(), totals.end());
    state.counters["median_ms"] = totals[totals.size() / 2];
    state.counters["min_ms"] = totals.front();
}
void BM_SelfOrgCycle100k(benchmark::State& state) {
    runCycle100k(state, benchParams());
}
BENCHMARK(BM_SelfOrgCycle100k)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(8);

/// The same for the conifer preset at ~100k internodes.
void BM_SelfOrgCycle100kConifer(benchmark::State& state) {
    runCycle100k(state, coniferParams());
}
BENCHMARK(BM_SelfOrgCycle100kConifer)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(8);

void BM_SelfOrgTree500k(benchmark::State& state) {
    const bool naive = state.range(0) != 0;
    std::size_t size = 0;
    int cycles = 0;
    for (auto _ : state) {
        SelfOrganizingSimulation sim({{glm::vec3(0), benchParams(), 1}}, {},
                                     SimulationOptions{naive, false});
        growTo(sim, 500'000);
        benchmark::DoNotOptimize(sim.results());
        size = sim.metamers().size();
        cycles = sim.cycle();
    }
    state.counters["internodes"] = static_cast<double>(size);
    state.counters["cycles"] = cycles;
}
BENCHMARK(BM_SelfOrgTree500k)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

/// 30 trees 6 m apart in one shadow grid, grown until the stand holds 10,000 internodes per
/// tree on average (the cycle count is found once, outside the timing, then fixed).
void BM_SelfOrgStand30(benchmark::State& state) {
    const bool naive = state.range(0) != 0;
    auto stand = [](int cycles) {
        std::vector<StandTree> trees;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 5; ++j) {
                SelfOrganizingParams p = benchParams();
                p.cycles = cycles;
                trees.push_back(
                    {glm::vec3(i * 6.0f, 0, j * 6.0f), p, static_cast<std::uint64_t>(10 * i + j)});
            }
        return trees;
    };
    int cycles = 0;
    {
        SelfOrganizingSimulation probe(stand(200), {});
        while (probe.metamers().size() < 300'000 && !probe.done())
            probe.step();
        cycles = probe.cycle();
    }
    const std::vector<StandTree> trees = stand(cycles);
    std::size_t size = 0;
    for (auto _ : state) {
        SelfOrganizingSimulation sim(trees, {}, SimulationOptions{naive, false});
        while (!sim.done())
            sim.step();
        const auto results = sim.results();
        size = 0;
        for (const auto& r : results)
            size += r.internodes;
    }
    state.counters["internodes"] = static_cast<double>(size);
    state.counters["per_tree"] = static_cast<double>(size) / 30.0;
    state.counters["cycles"] = cycles;
}
BENCHMARK(BM_SelfOrgStand30)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

/// Borchert–Honda on the 100k tree: the linear scan (0) against per-bud path products (1).
void BM_SelfOrgBorchertHonda(benchmark::State& state) {
    SelfOrganizingSimulation sim({{glm::vec3(0), benchParams(), 1}}, {});
    growTo(sim, 100'000);
    std::vector<double> t, a;
    sim.evaluateLight(t, a);
    const MetamerTopology topo = sim.metamers().topology();
    std::vector<double> g(t.size());
    std::vector<std::int32_t> c(t.size());
    const AllocationParams p{4.0, 0.5};
    for (auto _ : state) {
        if (state.range(0) == 0) {
            gatherLight(topo, t, a, g, c);
            benchmark::DoNotOptimize(allocateBorchertHonda(topo, g, t, a, {&p, 1}));
        } else {
            benchmark::DoNotOptimize(allocateBorchertHondaNaive(topo, t, a, {&p, 1}));
        }
    }
    state.counters["internodes"] = static_cast<double>(t.size());
}
BENCHMARK(BM_SelfOrgBorchertHonda)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace
