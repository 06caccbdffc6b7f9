// Benchmarks of the geometry stage: turtle, tube meshing, OBJ formatting (against a plain
// std::ostream writer in the same run) and a 1,000-tree forest written to disk.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

#include <malloc.h>
#include <omp.h>
#include <unistd.h>

#include "../../core/common/testwords.h"
#include "../../core/lsystem/referenceturtle.h"
#include "../../core/mesh/referencetubemesh.h"
#include "engine/export/obj/objwriter.h"
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/lsystem/turtle.h"
#include "engine/mesh/leafcards.h"
#include "engine/mesh/leaftint.h"
#include "engine/mesh/treemesh.h"
#include "engine/mesh/tubemesh.h"
#include "engine/util/atomicfile.h"
#include "engine/util/memorypolicy.h"
#include "engine/util/random.h"

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
        settings.tubes.resolution = 8; // 20,8xx triangles: the "~20,000 per tree"
        return mesh::buildTreeMesh(s, settings);
    }();
    return m;
}

// Segments per second and time per segment (printed as a time).
void setSegmentCounters(benchmark::State& state, std::size_t segments) {
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * segments));
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["ns_per_segment"] = benchmark::Counter(
        static_cast<double>(segments),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

using InterpretFn = skel::Skeleton (*)(const lsys::ModuleString&, const lsys::TurtleSettings&,
                                       Progress&);

skel::Skeleton fastTurtle(const lsys::ModuleString& w, const lsys::TurtleSettings& t, Progress& p) {
    return lsys::interpret(w, t, p);
}
skel::Skeleton referenceTurtle(const lsys::ModuleString& w, const lsys::TurtleSettings& t,
                               Progress& p) {
    return lsys::reference::interpretReference(w, t, p);
}

void runTurtle(benchmark::State& state, const lsys::ModuleString& word,
               const lsys::TurtleSettings& settings, InterpretFn fn) {
    std::size_t segments = 0;
    for (auto _ : state) {
        skel::Skeleton s = fn(word, settings, noProgress());
        segments = s.segmentCount();
        benchmark::DoNotOptimize(s.position.data());
    }
    setSegmentCounters(state, segments);
}

// ABOP's F -> F[+F]F[-F]F from a three-stem axiom: 8 generations = 3 * 5^8 = 1.17M segments,
// about 2.2 modules per segment (the plain context-free word the 30 ns target refers to).
const lsys::Grammar& abopGrammar() {
    static const lsys::Grammar g = lsys::parseGrammar("generations: 8\nangle: 25.7\n"
                                                      "axiom: F[&F][^F]\n"
                                                      "F -> F[+F]F[-F]F\n");
    return g;
}
const lsys::ModuleString& abopWord() {
    static const lsys::ModuleString w = lsys::derive(abopGrammar());
    return w;
}

void BM_TurtleContextFree(benchmark::State& state) {
    runTurtle(state, abopWord(), lsys::TurtleSettings{}, fastTurtle);
}
BENCHMARK(BM_TurtleContextFree)->Unit(benchmark::kMillisecond);

// The same with glibc's default allocation policy, i.e. without sylva::keepFreedMemory():
// every skeleton array is a fresh mapping that the kernel faults in and zeroes, as in a
// process that generates one tree and exits.
void BM_TurtleContextFreeFreshMemory(benchmark::State& state) {
    constexpr int kGlibcDefault = 128 * 1024;
    ::mallopt(M_MMAP_THRESHOLD, kGlibcDefault);
    ::mallopt(M_TRIM_THRESHOLD, kGlibcDefault);
    ::malloc_trim(0);
    runTurtle(state, abopWord(), lsys::TurtleSettings{}, fastTurtle);
    keepFreedMemory();
}
BENCHMARK(BM_TurtleContextFreeFreshMemory)->Unit(benchmark::kMillisecond);

// The first, straightforward turtle (tests/core/lsystem/referenceturtle.h), same word.
void BM_TurtleContextFreeReference(benchmark::State& state) {
    runTurtle(state, abopWord(), lsys::TurtleSettings{}, referenceTurtle);
}
BENCHMARK(BM_TurtleContextFreeReference)->Unit(benchmark::kMillisecond);

// ~800k segments of a parametric 3D word with ~10 modules per segment, most with parameters.
void BM_TurtleParametric(benchmark::State& state) {
    runTurtle(state, bigWord(), turtleSettings(), fastTurtle);
}
BENCHMARK(BM_TurtleParametric)->Unit(benchmark::kMillisecond);

void BM_TurtleParametricReference(benchmark::State& state) {
    runTurtle(state, bigWord(), turtleSettings(), referenceTurtle);
}
BENCHMARK(BM_TurtleParametricReference)->Unit(benchmark::kMillisecond);

// derive + interpret of the ABOP word above (1.17M segments); time_per_1M_segments is the
// figure the "1M-segment skeleton in <= 60 ms" target is checked against.
void runExpandAndInterpret(benchmark::State& state, InterpretFn fn) {
    std::size_t segments = 0;
    for (auto _ : state) {
        const lsys::ModuleString word = lsys::derive(abopGrammar());
        skel::Skeleton s = fn(word, lsys::TurtleSettings{}, noProgress());
        segments = s.segmentCount();
        benchmark::DoNotOptimize(s.position.data());
    }
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["time_per_1M_segments"] = benchmark::Counter(
        static_cast<double>(segments) / 1e6,
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
void BM_ExpandAndInterpret1M(benchmark::State& state) {
    runExpandAndInterpret(state, fastTurtle);
}
BENCHMARK(BM_ExpandAndInterpret1M)->Unit(benchmark::kMillisecond);
void BM_ExpandAndInterpret1MReference(benchmark::State& state) {
    runExpandAndInterpret(state, referenceTurtle);
}
BENCHMARK(BM_ExpandAndInterpret1MReference)->Unit(benchmark::kMillisecond);

// derive alone, to split the pair above.
void BM_Expand1M(benchmark::State& state) {
    for (auto _ : state) {
        const lsys::ModuleString word = lsys::derive(abopGrammar());
        benchmark::DoNotOptimize(word.symbols.data());
    }
}
BENCHMARK(BM_Expand1M)->Unit(benchmark::kMillisecond);

using AppendTubesFn = void (*)(mesh::Mesh&, const skel::Skeleton&, const mesh::TubeSettings&,
                               Progress&);

// A fresh mesh per iteration (first-touch page faults included, as in a real export).
void runTubeMesh(benchmark::State& state, AppendTubesFn fn) {
    const skel::Skeleton& s = bigSkeleton();
    mesh::TubeSettings settings;
    settings.resolution = 8;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    std::size_t vertices = 0;
    {
        // Untimed warm-up: the first ~600 MB a process takes from this VM are slow to fault in
        // (host-side first touch, ~0.5 s), which is not the mesher's cost.
        mesh::Mesh warm;
        fn(warm, s, settings, noProgress());
    }
    for (auto _ : state) {
        mesh::Mesh m;
        fn(m, s, settings, noProgress());
        vertices = m.vertexCount();
        benchmark::DoNotOptimize(m.positions.data());
    }
    omp_set_num_threads(saved);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * vertices));
    state.counters["vertices"] = static_cast<double>(vertices);
}

void BM_TubeMesh(benchmark::State& state) {
    runTubeMesh(state, mesh::appendTubes);
}
BENCHMARK(BM_TubeMesh)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond);

// Leaf colour variation (issue #33): tinting 100k leaf cards (a large broadleaf has 5-10k
// cluster cards, 20-40k single ones), the oak's library spread and patches; against the cost
// of making those cards (appendLeafCards), same run.
const std::vector<skel::Leaf>& manyLeaves() {
    static const std::vector<skel::Leaf> leaves = [] {
        std::vector<skel::Leaf> out(100000);
        Rng rng(5);
        for (skel::Leaf& l : out) {
            l.position = {rng.uniformf(-6, 6), rng.uniformf(2, 12), rng.uniformf(-6, 6)};
            l.orientation = glm::angleAxis(rng.uniformf(0, 6.28f), glm::vec3(0, 1, 0));
            l.size = 0.1f;
        }
        return out;
    }();
    return leaves;
}

void BM_LeafTint(benchmark::State& state) {
    mesh::Mesh m;
    mesh::appendLeafCards(m, manyLeaves(), {});
    const mesh::LeafColorVariation spread{6.0, 0.2, 0.2};
    for (auto _ : state) {
        m.colors.clear();
        mesh::tintLeafCards(m, 0, spread, {0.26f, 0.40f, 0.12f}, 1.5, 7);
        benchmark::DoNotOptimize(m.colors.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * manyLeaves().size()));
}
BENCHMARK(BM_LeafTint)->Unit(benchmark::kMillisecond);

void BM_LeafCards(benchmark::State& state) {
    for (auto _ : state) {
        mesh::Mesh m;
        mesh::appendLeafCards(m, manyLeaves(), {});
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * manyLeaves().size()));
}
BENCHMARK(BM_LeafCards)->Unit(benchmark::kMillisecond);

// The first, straightforward mesher (tests/core/mesh/referencetubemesh.cpp), same input.
void BM_TubeMeshReference(benchmark::State& state) {
    runTubeMesh(state, mesh::reference::appendTubesReference);
}
BENCHMARK(BM_TubeMeshReference)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond);

// Steady state of re-meshing (editor parameter edits): the mesh's buffers are reused, so the
// time is the meshing itself rather than first-touch page faults of ~600 MB of fresh memory.
void BM_TubeMeshReusedBuffers(benchmark::State& state) {
    const skel::Skeleton& s = bigSkeleton();
    mesh::TubeSettings settings;
    settings.resolution = 8;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    mesh::Mesh m;
    mesh::appendTubes(m, s, settings); // untimed: allocates the buffers the loop reuses
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
std::vector<exporter::ObjObject> forest() {
    const mesh::Mesh& m = treeMesh();
    std::vector<exporter::ObjObject> out;
    for (int i = 0; i < 1000; ++i)
        out.push_back(
            {"tree_" + std::to_string(i), &m,
             glm::translate(glm::mat4(1.0f), glm::vec3(10.0f * (i % 32), 0, 10.0f * (i / 32)))});
    return out;
}

std::filesystem::path forestPath() {
    return std::filesystem::temp_directory_path() / "sylva_bench_forest.obj";
}

// File sizes of the forest per option set (0 default, 1 compact), for BM_DiskFloor.
std::uint64_t gForestBytes[2] = {0, 0};

std::uint64_t forestBytes(int compact) {
    if (gForestBytes[compact] == 0) {
        const auto objs = forest();
        const exporter::ObjOptions o =
            compact ? exporter::ObjOptions::compact() : exporter::ObjOptions{};
        std::uint64_t bytes = 0;
        exporter::ObjOffsets offsets;
        std::string text;
        for (const auto& obj : objs) {
            text.clear();
            exporter::appendObj(text, obj, offsets, o);
            bytes += text.size();
        }
        gForestBytes[compact] = bytes;
    }
    return gForestBytes[compact];
}

// Untimed: writes back what earlier benchmarks left dirty in the page cache, so that this
// run is not throttled for their gigabytes.
void settleDisk(benchmark::State& state) {
    state.PauseTiming();
    ::sync();
    state.ResumeTiming();
}

void runForest(benchmark::State& state, const exporter::ObjOptions& options, int slot) {
    const auto objs = forest();
    const auto path = forestPath();
    const int saved = omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        settleDisk(state);
        exporter::writeObjFile(path, objs, options);
    }
    omp_set_num_threads(saved);
    const auto bytes = std::filesystem::file_size(path);
    gForestBytes[slot] = bytes;
    state.counters["triangles_per_tree"] = static_cast<double>(treeMesh().triangleCount());
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    std::filesystem::remove(path);
}

// What `sylva-cli forest` writes: ObjOptions::compact() (0.1 mm positions, 3-decimal normals,
// 4-decimal uvs, relative face indices), atomic, no fsync.
void BM_ForestObjFile(benchmark::State& state) {
    runForest(state, exporter::ObjOptions::compact(), 1);
}
BENCHMARK(BM_ForestObjFile)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The engine's default options (`--full-precision`): micrometre positions, absolute indices.
void BM_ForestObjFileFullPrecision(benchmark::State& state) {
    runForest(state, exporter::ObjOptions{}, 0);
}
BENCHMARK(BM_ForestObjFileFullPrecision)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// The forest's default with ObjOptions::fsync (`--fsync`): returns once the file is on disk.
void BM_ForestObjFileFsync(benchmark::State& state) {
    exporter::ObjOptions o = exporter::ObjOptions::compact();
    o.fsync = true;
    runForest(state, o, 1);
}
BENCHMARK(BM_ForestObjFileFsync)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// What the file system alone allows: the same byte count as the forest file (compact:0
// default, 1 compact) written with 8 MiB fwrite blocks through AtomicFile, with fsync (like
// `dd conv=fsync`) or without. No formatting at all.
void BM_DiskFloor(benchmark::State& state) {
    const std::uint64_t bytes = forestBytes(static_cast<int>(state.range(0)));
    const Durability durability = state.range(1) ? Durability::Durable : Durability::Atomic;
    const std::string block(8u << 20, 'x');
    const auto path = forestPath();
    for (auto _ : state) {
        settleDisk(state);
        AtomicFile file(path, durability);
        for (std::uint64_t done = 0; done < bytes; done += block.size())
            file.write(std::string_view(block).substr(
                0, static_cast<std::size_t>(std::min<std::uint64_t>(block.size(), bytes - done))));
        file.commit();
    }
    state.counters["MB"] = static_cast<double>(bytes) / 1e6;
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
    std::filesystem::remove(path);
}
BENCHMARK(BM_DiskFloor)
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({0, 0})
    ->ArgNames({"compact", "fsync"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

} // namespace
