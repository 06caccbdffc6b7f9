#!/usr/bin/env bash
# Runs the obstacle harness under valgrind, beside the ASan runs of scripts/fuzz.sh. Debian's
# Assimp is not instrumented: ASan sees its out-of-bounds writes only when its allocator later
# meets the damage (findings 12 and 24) and never its out-of-bounds reads (finding 25). Valgrind
# reports both when they happen. The harness's libFuzzer loop is built without ASan
# (clang++ -fsanitize=fuzzer over the harness and the engine sources it needs, -lassimp) into
# build/fuzz-valgrind/, and run under memcheck at 100 to 200 executions a second.
#   scripts/fuzz-valgrind.sh [seconds, default 600]
# Inputs after which valgrind reported an error are saved in build/fuzz/findings/obstacle-valgrind/;
# the log is build/fuzz-valgrind/valgrind.log. Exit status 1 when valgrind reported any error.
# Needs clang (./test.sh installs it) and valgrind (apt-get install valgrind). Runs at nice 19.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
seconds=${1:-600}
command -v valgrind >/dev/null || { echo "fuzz-valgrind.sh: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
command -v clang++ >/dev/null || { echo "fuzz-valgrind.sh: needs clang++ (./test.sh installs it)" >&2; exit 2; }
out=build/fuzz-valgrind findings=build/fuzz/findings/obstacle-valgrind corpus=build/fuzz/long-corpus/obstacle
mkdir -p "$out" "$findings" "$corpus"
bin=$out/fuzz_obstacle_valgrind
sources=(tests/fuzz/obstacle_fuzzer.cpp tests/fuzz/valgrind/counting_wrapper.cpp
  core/engine/environment/obstaclemesh.cpp core/engine/environment/meshfilecheck.cpp
  core/engine/environment/fbxcheck.cpp core/engine/environment/scenegraphwalk.cpp
  core/engine/util/value.cpp core/engine/util/error.cpp core/engine/util/atomicfile.cpp)
if [[ ! -x $bin ]] || [[ -n $(find "${sources[@]}" core/engine/environment core/engine/util -newer "$bin" 2>/dev/null | head -n 1) ]]; then
  echo "fuzz-valgrind.sh: building $bin"
  nice -n 19 clang++ -std=c++20 -O1 -gdwarf-4 -fsanitize=fuzzer -DGLM_ENABLE_EXPERIMENTAL \
    -Icore -Itests/fuzz -DLLVMFuzzerTestOneInput=sylvaHarnessInput \
    tests/fuzz/obstacle_fuzzer.cpp -c -o "$out/harness.o" || exit 1
  nice -n 19 clang++ -std=c++20 -O1 -gdwarf-4 -fsanitize=fuzzer -DGLM_ENABLE_EXPERIMENTAL -Icore \
    "$out/harness.o" "${sources[@]:1}" -lassimp -o "$bin" || exit 1
fi
log=$out/valgrind.log
echo "fuzz-valgrind.sh: obstacle under valgrind for $seconds s (log: $log)"
start=$(date +%s)
dirs=("$corpus" tests/fuzz/corpus/obstacle tests/fuzz/regressions/obstacle)
# libFuzzer's own memory limits need its malloc hooks, which valgrind replaces: off.
SYLVA_VALGRIND_FINDINGS=$findings nice -n 19 valgrind --error-exitcode=0 --undef-value-errors=no \
  --num-callers=30 "$bin" -rss_limit_mb=0 -malloc_limit_mb=0 -timeout=60 -max_len=8192 \
  -dict=tests/fuzz/dicts/obstacle.dict -max_total_time="$seconds" -print_final_stats=1 \
  "${dirs[@]}" >"$log" 2>&1
elapsed=$(($(date +%s) - start))
execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
errors=$(grep -c 'SYLVA-VALGRIND:' "$log")
if [[ -z $execs ]]; then
  echo "fuzz-valgrind.sh: the harness did not finish under valgrind; see $log" >&2
  exit 1
fi
line="$(date -u +%FT%TZ) obstacle-valgrind execs=${execs:-?} seconds=$elapsed valgrind-errors=$errors"
echo "$line" | tee -a build/fuzz/fuzz-summary.txt
if [[ $errors != 0 ]]; then
  echo "fuzz-valgrind.sh: valgrind reported errors; the inputs are in $findings/, the reports in $log" >&2
  exit 1
fi
