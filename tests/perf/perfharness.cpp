#include "perfharness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "engine/util/x86intrinsics.h"

namespace sylva::perf {

namespace {

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

volatile std::uint64_t gSink = 0;

/// The kernels' path this run takes (chosen at run time, SYLVA_NO_AVX512 / SYLVA_NO_AVX): the
/// AVX-512 kernels are up to 2.4x the SSE2 ones, so each path has its own baselines
/// (`ratio_by_path`), and a 2x slowdown fails the case on each.
const char* simdPath() {
#if defined(SYLVA_X86_INTRINSICS)
    return simd::useAvx512() ? "avx512" : simd::useAvx() ? "avx" : "sse2";
#else
    return "plain";
#endif
}

/// The calibration workload: a fixed mix of integer hashing, float arithmetic with a square root
/// and scattered reads and writes over 2 MiB (the L2/L3 traffic of a tree's arrays), about 11 ms
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

int usage(const std::map<std::string, Case>& cases) {
    std::fprintf(stderr, "usage: <program> <case> [--baselines FILE] [--reps N] [--update] "
                         "[--expect-slower]\ncases:");
    for (const auto& [name, c] : cases)
        std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, "\n");
    return 2;
}

} // namespace

void sink(std::uint64_t value) {
    gSink = gSink + value;
}

int runGate(int argc, char** argv, std::map<std::string, Case> all) {
    if (argc < 2) return usage(all);
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
            return usage(all);
    }
    auto it = all.find(name);
    if (it == all.end()) return usage(all);
    Case& c = it->second;
    if (reps == 0) reps = c.reps;
    int slowdown = 1;
    if (const char* s = std::getenv("SYLVA_PERF_SLOWDOWN")) slowdown = std::max(1, std::atoi(s));

    // One thread: the figure must not depend on what else the machine runs.
    omp_set_num_threads(1);
    c.prepare();
    std::size_t items = 0;
    if (c.warm) items = c.run(); // caches, the allocator's pools, lazy statics
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
    const char* path = simdPath();
    if (update) {
        nlohmann::json& entry = baselines["cases"][name];
        if (entry.contains("ratio_by_path"))
            entry["ratio_by_path"][path] = ratio;
        else
            entry["ratio"] = ratio;
        baselines["cases"][name]["what"] = c.what;
        if (!baselines.contains("tolerance")) baselines["tolerance"] = 1.5;
        std::ofstream(baselinesPath) << baselines.dump(2) << "\n";
        std::printf("  baseline of %s (%s path) written to %s\n", name.c_str(), path,
                    baselinesPath.c_str());
        return 0;
    }
    if (!baselines.contains("cases") || !baselines["cases"].contains(name)) {
        std::fprintf(stderr, "perf_gate: no baseline for '%s' in %s\n", name.c_str(),
                     baselinesPath.c_str());
        return 2;
    }
    // The path's own baseline where the case has one, else the case's.
    const nlohmann::json& entry = baselines["cases"][name];
    const bool byPath = entry.contains("ratio_by_path") && entry["ratio_by_path"].contains(path);
    const double base =
        byPath ? entry["ratio_by_path"][path].get<double>() : entry["ratio"].get<double>();
    const double tolerance = baselines.value("tolerance", 1.5);
    const double limit = base * tolerance;
    const bool slower = ratio > limit;
    std::printf("  baseline %.6g (%s), limit %.6g (x%.2f): %.2fx the baseline: %s\n", base,
                byPath ? (std::string(path) + " path").c_str() : "every path", limit, tolerance,
                ratio / base, slower ? "SLOWER than the gate allows" : "within");
    if (expectSlower) {
        std::printf("  --expect-slower: %s\n",
                    slower ? "caught, as expected" : "NOT caught: the gate misses this slowdown");
        return slower ? 0 : 1;
    }
    return slower ? 3 : 0;
}

} // namespace sylva::perf
