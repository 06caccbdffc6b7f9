// Wind (#31): generating a tree with its wind data and rig against the same tree without.
// Target: ≤ +15 % (docs/performance.md). Every iteration grows the tree from a fresh Evaluator
// (no cached node results), as sylva-cli tree does:
//   - Static: the species as it is (tube_mesh without node ids or wind data);
//   - WindData: tube_mesh wind_data (per-vertex node ids, what the wind model needs, docs/wind.md);
//   - WindRig: WindData plus the rig (≤ 64 bones) and the skin weights (≤ 4 per vertex);
//   - WindRigClip: WindRig plus the 4 s, 30 fps clip baked and the per-vertex channels the
//     writers store (wind::addWindData, 128 bytes a vertex): what a wind export adds on top.
// Args: the preset (0 English oak, 1 alder). Counters: vertices, bones.
#include <benchmark/benchmark.h>

#include <QString>

#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/nodes/meshnodes.h"
#include "engine/wind/windelements.h"
#include "engine/wind/windmodel.h"
#include "engine/wind/windrig.h"

using namespace sylva;

namespace {

enum class Mode { Static, WindData, WindRig, WindRigClip };

const graph::SpeciesGraph& preset(int which) {
    static const graph::SpeciesGraph oak =
        doc::loadSpecies(QStringLiteral(SYLVA_PRESETS_DIR "/english-oak.json"));
    static const graph::SpeciesGraph alder =
        doc::loadSpecies(QStringLiteral(SYLVA_PRESETS_DIR "/alder.json"));
    return which == 0 ? oak : alder;
}

void grow(benchmark::State& state, Mode mode) {
    graph::registerBuiltinNodeTypes();
    graph::SpeciesGraph g = preset(static_cast<int>(state.range(0)));
    if (mode != Mode::Static)
        for (graph::NodeDesc& n : g.nodes)
            if (n.type == "tube_mesh") n.params.objectRef()["wind_data"] = Value(true);
    const wind::WindSettings windSettings;
    const wind::RigSettings rigSettings;
    std::size_t vertices = 0, bones = 0;
    for (auto _ : state) {
        graph::Evaluator e(g);
        const graph::NodeOutput& out = e.evaluate(7);
        vertices = out.mesh->vertexCount();
        if (mode == Mode::WindRig || mode == Mode::WindRigClip) {
            const wind::WindElements elements = wind::buildWindElements(*out.skeleton);
            const wind::Rig rig = wind::buildRig(elements, *out.skeleton, rigSettings);
            const wind::SkinWeights weights = wind::skinWeights(rig, elements, *out.mesh);
            benchmark::DoNotOptimize(weights);
            bones = rig.joints.size();
            if (mode == Mode::WindRigClip) {
                const wind::WindClip clip =
                    wind::bakeClip(rig, elements, windSettings, rigSettings);
                benchmark::DoNotOptimize(clip);
                mesh::Mesh withData = *out.mesh;
                wind::addWindData(withData, *out.skeleton);
                benchmark::DoNotOptimize(withData.wind.data());
            }
        }
    }
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["bones"] = static_cast<double>(bones);
}

void BM_TreeStatic(benchmark::State& s) {
    grow(s, Mode::Static);
}
void BM_TreeWindData(benchmark::State& s) {
    grow(s, Mode::WindData);
}
void BM_TreeWindRig(benchmark::State& s) {
    grow(s, Mode::WindRig);
}
void BM_TreeWindRigClip(benchmark::State& s) {
    grow(s, Mode::WindRigClip);
}

} // namespace

BENCHMARK(BM_TreeStatic)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TreeWindData)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TreeWindRig)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TreeWindRigClip)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
