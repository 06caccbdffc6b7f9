// The performance gate (issue #41, ctest label `perf`): each case times one path of Sylva
// against a fixed calibration workload measured in the same process, interleaved with it, and
// compares the ratio with the baseline committed in tests/perf/baselines.json.
//
//   perf_gate <case> [--baselines FILE] [--reps N] [--update] [--expect-slower]
//
// A sample is the process CPU time of one calibration run followed by one run of the case (on
// one OpenMP thread, so the other users of a shared machine do not enter the figure); the
// figure is min(case) / min(calibration) over the repetitions (the minimum resists noise: a
// disturbance only ever adds time). The case fails when that ratio exceeds the baseline's ratio
// times the file's tolerance (exit status 3). Wall-clock times are asserted nowhere else.
//
// SYLVA_PERF_SLOWDOWN=k (a whole number, default 1) repeats the measured work k times per
// sample: the harness's own way to prove that a k-fold slowdown is caught (ctest
// perf_gate_catches_2x runs a case with k = 2 and expects exit status 3; --expect-slower
// inverts the verdict for that). --update writes the measured ratio into the baselines file
// (docs/performance.md: how and when to update a baseline).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QString>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <unistd.h>

#include "document/project.h"
#include "document/scenebuild.h"
#include "document/speciesfile.h"
#include "engine/export/treeexport.h"
#include "engine/forest/forestbuild.h"
#include "engine/graph/graph.h"
#include "engine/growth/envelope.h"
#include "engine/growth/spacecolonization.h"
#include "engine/lsystem/derivation.h"
#include "engine/lsystem/grammar.h"
#include "engine/mesh/mesh.h"
#include "engine/nodes/meshnodes.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/memorypolicy.h"

using namespace sylva;

namespace {

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

volatile std::uint64_t gSink = 0;

/// The calibration workload: a fixed mix of integer hashing, float arithmetic with a square root
/// and scattered reads and writes over 2 MiB (the L2/L3 traffic of a tree's arrays), about 25 ms
/// on the reference machine. Deterministic; the same instructions every run.
void calibrate() {
    constexpr std::size_t kFloats = std::size_t{1} << 19; // 2 MiB
    static std::vector<float> a(kFloats);
    for (std::size_t i = 0; i < kFloats; ++i)
        a[i] = static_cast<float>(i & 1023u) * 0.001f;
    std::uint64_t x = 0x9E3779B97F4A7C15ull, h = 0;
    float acc = 0.0f;
    for (int i = 0; i < 6'000'000; ++i) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        const std::size_t k = static_cast<std::size_t>(x) & (kFloats - 1);
        const float v = a[k];
        acc += std::sqrt(v * v + 1.0f) * 0.5f;
        a[k] = v * 0.999f + 0.001f * acc;
        h = (h ^ (x >> 11)) * 0x100000001b3ull;
    }
    gSink = gSink + h + static_cast<std::uint64_t>(acc);
}

struct Case {
    std::string what;              ///< one line: the path measured
    std::function<void()> prepare; ///< untimed, once
    /// One run of the measured path; returns the number of items it made (internodes for a
    /// per-internode figure), or 0.
    std::function<std::size_t()> run;
    std::string unit; ///< what the reported figure is per ("tree", "internode", ...)
    int reps = 9;
};

QString source(const char* relative) {
    return QString::fromStdString((std::filesystem::path(SYLVA_SOURCE_DIR) / relative).string());
}

Case speciesCase(const char* preset, std::uint64_t seed, bool perInternode) {
    auto g = std::make_shared<graph::SpeciesGraph>();
    Case c;
    c.prepare = [g, preset] {
        *g = doc::loadSpecies(source((std::string("presets/") + preset).c_str()));
    };
    c.run = [g, seed, perInternode]() -> std::size_t {
        graph::Evaluator e(*g); // fresh: no cached node results, as `sylva-cli tree` grows it
        const graph::NodeOutput& out = e.evaluate(seed);
        gSink = gSink + out.mesh->triangleCount();
        return perInternode && out.skeleton ? out.skeleton->size() : 0;
    };
    return c;
}

Case forestCase(const char* project) {
    auto scene = std::make_shared<forest::ForestScene>();
    Case c;
    c.reps = 5;
    c.prepare = [scene, project] {
        *scene = doc::makeForestScene(doc::loadProject(source(project)));
    };
    c.run = [scene]() -> std::size_t {
        const std::filesystem::path out =
            std::filesystem::temp_directory_path() /
            ("sylva-perf-gate-" + std::to_string(::getpid()) + ".obj");
        {
            // As `sylva-cli forest f.obj` writes it: compact OBJ, the camera LOD, instancing.
            exporter::TreeExporter exporter(out, exporter::ObjChoices{false, true});
            forest::ForestOptions options;
            options.meshInstances = !exporter.writesInstances();
            options.onVariants = [&](const std::vector<forest::ForestVariant>& variants) {
                std::vector<exporter::ExportVariant> v;
                for (const forest::ForestVariant& variant : variants)
                    v.push_back({variant.name, variant.mesh, variant.species, variant.index});
                exporter.addVariants(v);
            };
            forest::buildForest(*scene, options, [&](const std::vector<forest::ForestTree>& batch) {
                std::vector<exporter::ExportTree> trees;
                for (const forest::ForestTree& t : batch)
                    trees.push_back({t.name, t.mesh, t.instance.position, t.instance.rotation,
                                     t.instance.scale * t.instance.growth, t.variant, t.instance.id,
                                     t.instance.species});
                exporter.add(trees);
            });
            exporter.commit();
        }
        std::error_code ec;
        std::filesystem::remove(out, ec);
        std::filesystem::remove(std::filesystem::path(out).replace_extension(".mtl"), ec);
        std::filesystem::remove_all(out.parent_path() / "textures", ec);
        return 0;
    };
    return c;
}

std::map<std::string, Case> cases() {
    std::map<std::string, Case> all;
    Case oak = speciesCase("english-oak.json", 2, false);
    oak.what = "English oak (presets/english-oak.json, seed 2) grown and meshed, warm, 1 thread";
    oak.unit = "tree";
    oak.reps = 15;
    all["oak"] = oak;

    Case so = speciesCase("so-broadleaf.json", 1, true);
    so.what = "self-organizing broadleaf (presets/so-broadleaf.json) grown and meshed, per "
              "internode, 1 thread";
    so.unit = "internode";
    so.reps = 9;
    all["so-broadleaf"] = so;

    Case sc;
    auto points = std::make_shared<std::vector<glm::vec3>>();
    sc.what = "space colonization of 10,000 attraction points in a 4.5 m sphere (the "
              "reference's round crown), 1 thread";
    sc.unit = "tree";
    sc.reps = 15;
    sc.prepare = [points] { *points = growth::Envelope::sphere({0, 6, 0}, 4.5f).sample(10000, 7); };
    sc.run = [points]() -> std::size_t {
        growth::ColonizationParams p;
        p.trunkHeight = 2.0f;
        const growth::ColonizationResult r = growth::colonize(*points, p, nullptr);
        gSink = gSink + r.skeleton.size();
        return 0;
    };
    all["spacecol"] = sc;

    Case ls;
    ls.what = "L-system expansion: F -> F[+F]F[-F]F 8 generations (fast path) and a parametric "
              "grammar with conditions 11 generations (general path)";
    ls.unit = "expansion";
    ls.reps = 15;
    auto grammars = std::make_shared<std::vector<lsys::Grammar>>();
    ls.prepare = [grammars] {
        grammars->push_back(lsys::parseGrammar("axiom: F\nF -> F[+F]F[-F]F\n"));
        grammars->push_back(
            lsys::parseGrammar("define: r = 0.9\naxiom: A(1, 0.2)\n"
                               "A(l, w) : l > 0.01 -> !(w)F(l)[&(30)A(l*r, w*0.7)]"
                               "/(137.5)[&(30)A(l*r, w*0.7)]/(137.5)A(l*r, w*0.7)\n"));
    };
    ls.run = [grammars]() -> std::size_t {
        lsys::DeriveOptions o;
        o.generations = 8;
        gSink = gSink + lsys::derive((*grammars)[0], o).size();
        o.generations = 11;
        gSink = gSink + lsys::derive((*grammars)[1], o).size();
        return 0;
    };
    all["lsystem"] = ls;

    Case f1000 = forestCase("resources/demo/bench-1000.sylva");
    f1000.what = "1,000-tree forest (resources/demo/bench-1000.sylva) to a compact OBJ with "
                 "the camera LOD, 1 thread";
    f1000.unit = "forest";
    all["forest-1000"] = f1000;

    Case library = forestCase("resources/demo/library.sylva");
    library.what = "library.sylva (12 hand-placed trees) to a compact OBJ, 1 thread";
    library.unit = "forest";
    all["library"] = library;
    return all;
}

int usage() {
    std::fprintf(stderr, "usage: perf_gate <case> [--baselines FILE] [--reps N] [--update] "
                         "[--expect-slower]\ncases:");
    for (const auto& [name, c] : cases())
        std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, "\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    keepFreedMemory();
    graph::registerBuiltinNodeTypes();
    if (argc < 2) return usage();
    const std::string name = argv[1];
    std::filesystem::path baselinesPath =
        std::filesystem::path(SYLVA_SOURCE_DIR) / "tests/perf/baselines.json";
    bool update = false, expectSlower = false;
    int reps = 0;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--baselines" && i + 1 < argc)
            baselinesPath = argv[++i];
        else if (a == "--reps" && i + 1 < argc)
            reps = std::max(1, std::atoi(argv[++i]));
        else if (a == "--update")
            update = true;
        else if (a == "--expect-slower")
            expectSlower = true;
        else
            return usage();
    }
    std::map<std::string, Case> all = cases();
    auto it = all.find(name);
    if (it == all.end()) return usage();
    Case& c = it->second;
    if (reps == 0) reps = c.reps;
    int slowdown = 1;
    if (const char* s = std::getenv("SYLVA_PERF_SLOWDOWN")) slowdown = std::max(1, std::atoi(s));

    // One thread: the figure must not depend on what else the machine runs.
    omp_set_num_threads(1);
    c.prepare();
    std::size_t items = c.run(); // warm: caches, the allocator's pools, lazy statics
    calibrate();
    double minCal = std::numeric_limits<double>::max(), minRun = minCal;
    std::vector<double> ratios;
    for (int r = 0; r < reps; ++r) {
        double t = cpuSeconds();
        calibrate();
        const double cal = cpuSeconds() - t;
        t = cpuSeconds();
        for (int k = 0; k < slowdown; ++k)
            items = c.run();
        const double run = cpuSeconds() - t;
        minCal = std::min(minCal, cal);
        minRun = std::min(minRun, run);
        ratios.push_back(run / cal);
    }
    const double perItem = items > 0 ? minRun / static_cast<double>(items) : minRun;
    const double ratio = perItem / minCal;
    std::printf("perf_gate %s: %s\n", name.c_str(), c.what.c_str());
    std::printf("  %d repetitions%s: min %.3f ms CPU a run (%.3f us a %s), calibration min "
                "%.3f ms\n",
                reps, slowdown > 1 ? (" x" + std::to_string(slowdown) + " slowdown").c_str() : "",
                1e3 * minRun, 1e6 * perItem, c.unit.c_str(), 1e3 * minCal);
    std::printf("  ratio %.6g (per %s over calibration; sample ratios", ratio, c.unit.c_str());
    for (double q : ratios)
        std::printf(" %.4g", q / (items > 0 ? static_cast<double>(items) : 1.0));
    std::printf(")\n");

    nlohmann::json baselines;
    {
        std::ifstream in(baselinesPath);
        if (in) baselines = nlohmann::json::parse(in, nullptr, false);
        if (baselines.is_discarded() || !baselines.is_object())
            baselines = nlohmann::json::object();
    }
    if (update) {
        baselines["cases"][name]["ratio"] = ratio;
        baselines["cases"][name]["what"] = c.what;
        if (!baselines.contains("tolerance")) baselines["tolerance"] = 1.5;
        std::ofstream(baselinesPath) << baselines.dump(2) << "\n";
        std::printf("  baseline of %s written to %s\n", name.c_str(), baselinesPath.c_str());
        return 0;
    }
    if (!baselines.contains("cases") || !baselines["cases"].contains(name)) {
        std::fprintf(stderr, "perf_gate: no baseline for '%s' in %s\n", name.c_str(),
                     baselinesPath.c_str());
        return 2;
    }
    const double base = baselines["cases"][name]["ratio"].get<double>();
    const double tolerance = baselines.value("tolerance", 1.5);
    const double limit = base * tolerance;
    const bool slower = ratio > limit;
    std::printf("  baseline %.6g, limit %.6g (x%.2f): %.2fx the baseline: %s\n", base, limit,
                tolerance, ratio / base, slower ? "SLOWER than the gate allows" : "within");
    if (expectSlower) {
        std::printf("  --expect-slower: %s\n",
                    slower ? "caught, as expected" : "NOT caught: the gate misses this slowdown");
        return slower ? 0 : 1;
    }
    return slower ? 3 : 0;
}
