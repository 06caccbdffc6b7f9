#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through ctest (ccache when installed):
#   1. Release build with -Werror: engine GoogleTests, QtTest suites under xvfb-run (the
#      artist's day among them), the performance gate (label perf), CLI
#      end-to-end tests, the clang-format check; benchmarks are built, not run.
#   2. The engine and document-core tests (label engine) again under AddressSanitizer +
#      UndefinedBehaviorSanitizer.
#   3. The libFuzzer harnesses (clang, ASan + UBSan; ctest label fuzz): each replays its corpus
#      and every past crash (tests/fuzz/regressions), then fuzzes for SYLVA_FUZZ_SECONDS (20 s).
#      scripts/fuzz.sh runs them longer.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/install-readers.sh

JOBS=${SYLVA_JOBS:-$(nproc)}
# ccache (CMakeLists.txt uses it when installed): paths relative to this checkout, so a clean
# clone elsewhere hits the cache a session warmed.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-8G}"
start=$(date +%s)

cmake --preset release >/dev/null
cmake --build --preset release -j "$JOBS"
ctest --preset release -j "$JOBS"

if [[ "${SYLVA_SKIP_ASAN:-0}" != 1 ]]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$JOBS"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j "$JOBS"
fi
if [[ "${SYLVA_SKIP_FUZZ:-0}" != 1 ]]; then
  cmake --preset fuzz -DSYLVA_FUZZ_SECONDS="${SYLVA_FUZZ_SECONDS:-20}" >/dev/null
  cmake --build --preset fuzz -j "$JOBS"
  # SYLVA_FUZZ_JOBS=1 runs one fuzzer at a time (a shared machine); CI runs $JOBS at once.
  ctest --preset fuzz -j "${SYLVA_FUZZ_JOBS:-$JOBS}"
fi
echo "test.sh: all test suites passed in $(( $(date +%s) - start )) s"
