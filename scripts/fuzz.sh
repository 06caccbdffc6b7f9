#!/usr/bin/env bash
# Runs every libFuzzer harness (or those named) for longer than ./test.sh does, one after the
# other, each growing its own corpus in build/fuzz/long-corpus/<name>/ (kept between runs).
#   scripts/fuzz.sh [seconds per harness, default 600] [harness...]
# Harnesses: grammar derive json species project fbxfix obstacle. A crash, leak, UBSan report,
# input slower than 10 s or process above 2 GB is a failure: the input is left in
# build/fuzz/findings/<name>/; fix the bug and add the input to tests/fuzz/regressions/<name>/.
# Prints one summary line per harness (executions, seconds, cov, ft, corpus size, result),
# also appended to build/fuzz/fuzz-summary.txt. Runs under nice -n 19.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
shift || true
harnesses=("$@")
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=(grammar derive json species project fbxfix obstacle)

./scripts/install-deps.sh || exit 1
JOBS=${SYLVA_JOBS:-$(nproc)}
cmake --preset fuzz >/dev/null || exit 1
cmake --build --preset fuzz -j "$JOBS" || exit 1

summary=build/fuzz/fuzz-summary.txt
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0"
failed=()
for name in "${harnesses[@]}"; do
  bin=build/fuzz/tests/fuzz/fuzz_$name
  [[ -x $bin ]] || { echo "fuzz.sh: no harness '$name'" >&2; failed+=("$name"); continue; }
  long=build/fuzz/long-corpus/$name findings=build/fuzz/findings/$name log=build/fuzz/fuzz-$name.log
  mkdir -p "$long" "$findings"
  dirs=("$long" "tests/fuzz/corpus/$name")
  [[ -d tests/fuzz/regressions/$name ]] && dirs+=("tests/fuzz/regressions/$name")
  echo "fuzz.sh: $name for $seconds s"
  start=$(date +%s)
  maxlen=8192 # as in run-fuzzer.sh: mutations stay small, large regressions are read whole
  [[ $name == fbxfix ]] && maxlen=32768
  OMP_NUM_THREADS=1 nice -n 19 "$bin" -rss_limit_mb=2048 -timeout=10 -max_len=$maxlen \
    -dict="tests/fuzz/dicts/$name.dict" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$findings/" "${dirs[@]}" >"$log" 2>&1
  status=$?
  elapsed=$(($(date +%s) - start))
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  last=$(grep -E '^#[0-9]+[[:space:]]' "$log" | tail -n 1)
  cov=$(grep -o 'cov: [0-9]*' <<<"$last" | grep -o '[0-9]*')
  ft=$(grep -o 'ft: [0-9]*' <<<"$last" | grep -o '[0-9]*')
  corp=$(grep -o 'corp: [0-9]*' <<<"$last" | grep -o '[0-9]*')
  result=ok
  if [[ $status != 0 ]]; then
    result="FAILED (status $status, see $log and $findings/)"
    failed+=("$name")
  fi
  line="$(date -u +%FT%TZ) $name execs=${execs:-?} seconds=$elapsed cov=${cov:-?} ft=${ft:-?} corpus=${corp:-?} $result"
  echo "$line" | tee -a "$summary"
done
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz.sh: failures in: ${failed[*]}" >&2
  exit 1
fi
