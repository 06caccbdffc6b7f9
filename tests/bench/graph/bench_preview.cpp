// The species editor's live preview: edit → new mesh for a 20,000-segment tree with leaves.
// The editor keeps one long-lived Evaluator per species, so an edit re-runs only the node it
// touched and what is downstream; the naive way builds a new Evaluator (everything again).
//   - a parameter of the last node (tube_mesh resolution, leaf_scale): only the mesher runs;
//   - a parameter of the generator (the lsystem's angle): everything downstream runs;
//   - the generator edit with rule tracing, as the editor's preview runs it (the derivation takes
//     its general path so every branch knows its rule: the click-to-rule feature);
//   - the same edits evaluated from scratch, for comparison;
//   - the vertices the viewport uploads for the new mesh (ui/generation/vertexdata.h), which the
//     preview's worker makes after the evaluation (the editor's species_preview.py compares that
//     with making them on the GUI thread).
// Counters: segments, triangles. docs/perf/editor.md has the figures (targets: ≤ 10 ms for a
// last-node parameter, ≤ 50 ms for an edit to a 20,000-segment tree).
#include <benchmark/benchmark.h>

#include <omp.h>

#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "ui/generation/vertexdata.h"

using namespace sylva::graph;
using sylva::Value;

namespace {

// 2 segments per A, 3 A's per A: 3^9 = 19,683 A's at the last generation, 19,682 segments.
const char* kGrammar = "generations: 9\n"
                       "angle: 28\n"
                       "step: 0.35\n"
                       "width: 0.25\n"
                       "width_factor: 0.75\n"
                       "axiom: A\n"
                       "A -> !F[&+A]/(137)[&-A]!F/(90)A J\n";

SpeciesGraph species(bool leaves) {
    SpeciesGraph g;
    g.name = "bench";
    g.nodes.push_back(NodeDesc{"grow", "lsystem", Value::Object{{"grammar", kGrammar}}, {}});
    if (leaves) {
        g.nodes.push_back(NodeDesc{
            "leaves", "leaves", Value::Object{{"placement", "tips"}, {"tip_count", 2}}, {"grow"}});
        g.nodes.push_back(
            NodeDesc{"mesh", "tube_mesh", Value::Object{{"resolution", 6}}, {"leaves"}});
    } else {
        g.nodes.push_back(
            NodeDesc{"mesh", "tube_mesh", Value::Object{{"resolution", 6}}, {"grow"}});
    }
    g.output = "mesh";
    return g;
}

void report(benchmark::State& state, const NodeOutput& out) {
    state.counters["segments"] = static_cast<double>(out.skeleton->segmentCount());
    state.counters["triangles"] = static_cast<double>(out.mesh->triangleCount());
}

/// Alternates \p node.\p key between two values and evaluates: the edit → mesh time.
void editAndEvaluate(benchmark::State& state, const std::string& node, const std::string& key,
                     Value a, Value b, bool incremental, bool traced = false) {
    registerBuiltinNodeTypes();
    omp_set_num_threads(static_cast<int>(state.range(1)));
    Evaluator kept(species(state.range(0) != 0));
    kept.setTraceSources(traced);
    kept.evaluate(1);
    bool flip = false;
    const NodeOutput* out = nullptr;
    for (auto _ : state) {
        flip = !flip;
        if (incremental) {
            kept.setParam(node, key, flip ? a : b);
            out = &kept.evaluate(1);
        } else {
            SpeciesGraph g = species(state.range(0) != 0);
            g.findNode(node)->params.objectRef()[key] = flip ? a : b;
            Evaluator fresh(std::move(g));
            out = &fresh.evaluate(1);
            benchmark::DoNotOptimize(out->mesh.get());
            report(state, *out);
            continue;
        }
        benchmark::DoNotOptimize(out->mesh.get());
    }
    if (out && incremental) report(state, *out);
}

void BM_PreviewLastNodeEdit(benchmark::State& state) {
    editAndEvaluate(state, "mesh", "leaf_scale", Value(1.0), Value(1.2), true);
}
void BM_PreviewLastNodeEdit_Naive(benchmark::State& state) {
    editAndEvaluate(state, "mesh", "leaf_scale", Value(1.0), Value(1.2), false);
}
void BM_PreviewResolutionEdit(benchmark::State& state) {
    editAndEvaluate(state, "mesh", "resolution", Value(6), Value(5), true);
}
void BM_PreviewGeneratorEdit(benchmark::State& state) {
    editAndEvaluate(state, "grow", "angle", Value(28.0), Value(30.0), true);
}
void BM_PreviewGeneratorEdit_Traced(benchmark::State& state) {
    editAndEvaluate(state, "grow", "angle", Value(28.0), Value(30.0), true, true);
}
void BM_PreviewGeneratorEdit_Naive(benchmark::State& state) {
    editAndEvaluate(state, "grow", "angle", Value(28.0), Value(30.0), false);
}

void BM_PreviewViewVertices(benchmark::State& state) {
    registerBuiltinNodeTypes();
    omp_set_num_threads(1);
    Evaluator ev(species(true));
    const sylva::mesh::Mesh& m = *ev.evaluate(1).mesh;
    for (auto _ : state) {
        const auto v = sylva::ui::interleaveVertices(m, {});
        benchmark::DoNotOptimize(v.data());
    }
    state.counters["vertices"] = static_cast<double>(m.vertexCount());
    state.counters["bytes"] = static_cast<double>(m.vertexCount() * sizeof(sylva::ui::ViewVertex));
}

} // namespace

BENCHMARK(BM_PreviewViewVertices)->Unit(benchmark::kMillisecond);

// Arguments: leaves (1: a leaves node adds leaf cards, 0: bare branches), OpenMP threads (the
// editor's preview uses 1: on a shared 2-core machine two spinning threads are slower).
BENCHMARK(BM_PreviewLastNodeEdit)->ArgsProduct({{0, 1}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewLastNodeEdit_Naive)
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewResolutionEdit)->ArgsProduct({{0, 1}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewGeneratorEdit)->ArgsProduct({{0, 1}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewGeneratorEdit_Traced)
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PreviewGeneratorEdit_Naive)
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond);
