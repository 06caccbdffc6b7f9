// Benchmarks of the geometry stage: turtle, tube meshing, OBJ formatting (against a plain
// std::ostream writer in the same run) and a 1,000-tree forest written to disk.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

#include <omp.h>

#include "../../core/geometry/testwords.h"
#include "engine/export/objwriter.h"
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/turtle.h"
#include "engine/mesh/lod.h"
#include "engine/mesh/tubemesh.h"

using namespace sylva;

namespace {

lsys::TurtleSettings turtleSettings() {
    lsys::TurtleSettings t;
    t.angleDegrees = 30;
    t.step = 0.5;
    t.width = 0.3;
    return t;
}

// About 800k segments with parameters, turns in 3D and pushes/pops.
const lsys::ModuleString& bigWord() {
    static const lsys::ModuleString word =
        sylva::testing::makeWord(sylva::testing::testTreeWord(12));
    return word;
}

const skel::Skeleton& bigSkeleton() {
    static const skel::Skeleton s = lsys::interpret(bigWord(), turtleSettings());
    return s;
}

// A tree of about 20,000 triangles (bark and leaves) for the OBJ benchmarks.
const mesh::Mesh& treeMesh() {
    static const mesh::Mesh m = [] {
        const auto s = lsys::interpret(sylva::testing::makeWord(sylva::testing::testTreeWord(6)),
                                       turtleSettings());
        mesh::TreeMeshSettings settings;
        settings.tubes.resolution = 6;
        return mesh::buildTreeMesh(s, settings);
    }();
    return m;
}

void BM_Turtle(benchmark::State& state) {
    const lsys::ModuleString& word = bigWord();
    std::size_t segments = 0;
    for (auto _ : state) {
        skel::Skeleton s = lsys::interpret(word, turtleSettings());
        segments = s.segmentCount();
        benchmark::DoNotOptimize(s.position.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * segments));
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["ns_per_segment"] = benchmark::Counter(
        static_cast<double>(segments),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Turtle)->Unit(benchmark::kMillisecond);

// About 1.2M segments (3 * 5^8): ABOP's F -> F[+F]F[-F]F from a three-stem axiom, expanded
// by the L-system engine and then interpreted.
void BM_ExpandAndInterpret1M(benchmark::State& state) {
    const lsys::Grammar g = lsys::parseGrammar("generations: 8\nangle: 25.7\n"
                                               "axiom: F[&F][^F]\n"
                                               "F -> F[+F]F[-F]F\n");
    std::size_t segments = 0;
    for (auto _ : state) {
        const lsys::ModuleString word = lsys::derive(g);
        skel::Skeleton s = lsys::interpret(word, lsys::TurtleSettings{});
        segments = s.segmentCount();
        benchmark::DoNotOptimize(s.position.data());
    }
    state.counters["segments"] = static_cast<double>(segments);
}
BENCHMARK(BM_ExpandAndInterpret1M)->Unit(benchmark::kMillisecond);

void BM_TubeMesh(benchmark::State& state) {
    const skel::Skeleton& s = bigSkeleton();
    mesh::TubeSettings settings;
    settings.resolution = 8;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    std::size_t vertices = 0;
    for (auto _ : state) {
        mesh::Mesh m = mesh::buildTubeMesh(s, settings);
        vertices = m.vertexCount();
        benchmark::DoNotOptimize(m.positions.data());
    }
    omp_set_num_threads(saved);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * vertices));
    state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_TubeMesh)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond);

// Steady state of re-meshing (editor parameter edits): the mesh's buffers are reused, so the
// time is the meshing itself rather than first-touch page faults of ~600 MB of fresh memory.
void BM_TubeMeshReusedBuffers(benchmark::State& state) {
    const skel::Skeleton& s = bigSkeleton();
    mesh::TubeSettings settings;
    settings.resolution = 8;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    mesh::Mesh m;
    for (auto _ : state) {
        m.positions.clear();
        m.normals.clear();
        m.uvs.clear();
        m.indices.clear();
        m.submeshes.clear();
        mesh::appendTubes(m, s, settings);
        benchmark::DoNotOptimize(m.positions.data());
    }
    omp_set_num_threads(saved);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * m.vertexCount()));
}
BENCHMARK(BM_TubeMeshReusedBuffers)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond);

// Ten trees as separate objects (~200k triangles).
std::vector<exporter::ObjObject> objects() {
    std::vector<exporter::ObjObject> out;
    for (int i = 0; i < 10; ++i)
        out.push_back({"tree_" + std::to_string(i), &treeMesh(),
                       glm::translate(glm::mat4(1.0f), glm::vec3(5.0f * i, 0, 0))});
    return out;
}

void BM_ObjFormat(benchmark::State& state) {
    const auto objs = objects();
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    std::size_t bytes = 0;
    for (auto _ : state) {
        std::string text = exporter::formatObj(objs);
        bytes = text.size();
        benchmark::DoNotOptimize(text.data());
    }
    omp_set_num_threads(saved);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_ObjFormat)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond);

// The straightforward writer the fast one is compared with: iostream formatting of the same
// content (fixed 6/5/4 decimals), into memory.
void BM_ObjOstreamBaseline(benchmark::State& state) {
    const auto objs = objects();
    std::size_t bytes = 0;
    for (auto _ : state) {
        std::ostringstream os;
        std::uint64_t base = 1;
        for (const auto& o : objs) {
            const mesh::Mesh& m = *o.mesh;
            os << "o " << o.name << '\n';
            for (const glm::vec3& p0 : m.positions) {
                const glm::vec3 p = glm::vec3(o.transform * glm::vec4(p0, 1.0f));
                os << std::fixed << std::setprecision(6) << "v " << p.x << ' ' << p.y << ' ' << p.z
                   << '\n';
            }
            for (const glm::vec2& t : m.uvs)
                os << std::setprecision(5) << "vt " << t.x << ' ' << t.y << '\n';
            for (const glm::vec3& n : m.normals)
                os << std::setprecision(4) << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
            for (std::size_t i = 0; i < m.indices.size(); i += 3) {
                os << 'f';
                for (int k = 0; k < 3; ++k) {
                    const std::uint64_t v = base + m.indices[i + static_cast<std::size_t>(k)];
                    os << ' ' << v << '/' << v << '/' << v;
                }
                os << '\n';
            }
            base += m.positions.size();
        }
        const std::string text = os.str();
        bytes = text.size();
        benchmark::DoNotOptimize(text.data());
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}
BENCHMARK(BM_ObjOstreamBaseline)->Unit(benchmark::kMillisecond);

// 1,000 trees of ~20,000 triangles written as one OBJ file (streaming, atomic).
void BM_ForestObjFile(benchmark::State& state) {
    const mesh::Mesh& m = treeMesh();
    std::vector<exporter::ObjObject> forest;
    for (int i = 0; i < 1000; ++i)
        forest.push_back(
            {"tree_" + std::to_string(i), &m,
             glm::translate(glm::mat4(1.0f), glm::vec3(10.0f * (i % 32), 0, 10.0f * (i / 32)))});
    const auto path = std::filesystem::temp_directory_path() / "sylva_bench_forest.obj";
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    for (auto _ : state)
        exporter::writeObjFile(path, forest);
    omp_set_num_threads(saved);
    state.counters["triangles_per_tree"] = static_cast<double>(m.triangleCount());
    state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    std::filesystem::remove(path);
}
BENCHMARK(BM_ForestObjFile)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace

BENCHMARK_MAIN();
