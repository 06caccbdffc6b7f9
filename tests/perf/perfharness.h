#pragma once
// The performance gate's harness (issue #41, ctest label `perf`; docs/performance.md#the-
// performance-gate), shared by perf_gate (the engine's and the document's paths) and
// perf_gate_viewport (the editor's viewport, under Xvfb): each case's CPU time against a fixed
// calibration workload timed in the same process, interleaved with it, compared with the ratio
// committed in tests/perf/baselines.json.
//
//   <program> <case> [--baselines FILE] [--reps N] [--update] [--expect-slower]
//
// A sample is the process CPU time of one calibration run followed by one run of the case; the
// figure is min(case) / min(calibration) over the repetitions (the minimum resists noise: a
// disturbance only ever adds time). The case fails when that ratio exceeds the baseline's ratio
// times the file's tolerance (exit status 3). Wall-clock times are asserted nowhere else.
//
// SYLVA_PERF_SLOWDOWN=k (a whole number, default 1) repeats the measured work k times per
// sample: the harness's own way to prove that a k-fold slowdown is caught (ctest
// perf_gate_catches_2x runs a case with k = 2 and expects exit status 3; --expect-slower
// inverts the verdict for that). --update writes the measured ratio into the baselines file.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

namespace sylva::perf {

/// One measured path.
struct Case {
    std::string what;              ///< one line: the path measured
    std::function<void()> prepare; ///< untimed, once
    /// One run of the measured path; returns the number of items it made (internodes for a
    /// per-internode figure, frames for a per-frame one), or 0.
    std::function<std::size_t()> run;
    std::string unit; ///< what the reported figure is per ("tree", "internode", ...)
    int reps = 9;
    /// One untimed run before the repetitions (caches, the allocator's pools, lazy statics).
    /// Off for the long cases: the minimum over the repetitions leaves the first run's extra
    /// costs out anyway.
    bool warm = true;
};

/// Keeps a result alive so that the measured work is not optimised away.
void sink(std::uint64_t value);

/// Parses the command line, measures the named case of \p cases and compares it with its
/// baseline; returns the process's exit status (0 within, 3 slower, 2 usage or no baseline).
int runGate(int argc, char** argv, std::map<std::string, Case> cases);

} // namespace sylva::perf
