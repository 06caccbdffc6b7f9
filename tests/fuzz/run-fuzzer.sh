#!/usr/bin/env bash
# One fuzz ctest: replays every input of corpus/<name>/ and regressions/<name>/ (each once, so a
# past crash, leak, timeout or memory blow-up fails the test again), then fuzzes for <seconds>
# with the dictionary dicts/<name>.dict. Any crash, leak, UBSan report, input slower than
# -timeout or process above -rss_limit_mb fails the test and leaves the input in <work>/artifacts.
# usage: run-fuzzer.sh <fuzzer> <name> <tests/fuzz folder> <work folder> <seconds>
set -uo pipefail
bin=$1 name=$2 src=$3 work=$4 seconds=$5
corpus=$src/corpus/$name regressions=$src/regressions/$name dict=$src/dicts/$name.dict
limits=(-rss_limit_mb=2048 -timeout=10)
export LSAN_OPTIONS="suppressions=$src/lsan.supp:print_suppressions=0"

fail() {
  echo "run-fuzzer: $name: FAILED: $*" >&2
  exit 1
}

rm -rf "$work" && mkdir -p "$work/corpus" "$work/artifacts" || exit 1
cd "$work" || exit 1
[[ -d $corpus ]] || fail "no seed corpus at $corpus"
inputs=()
for dir in "$corpus" "$regressions"; do
  [[ -d $dir ]] || continue
  while IFS= read -r -d '' f; do inputs+=("$f"); done < <(find "$dir" -type f -print0 | sort -z)
done
[[ ${#inputs[@]} -gt 0 ]] || fail "the seed corpus $corpus is empty"

echo "run-fuzzer: $name: replaying ${#inputs[@]} inputs"
if ! "$bin" "${limits[@]}" -artifact_prefix="$work/artifacts/" "${inputs[@]}" >replay.log 2>&1; then
  tail -n 60 replay.log >&2
  fail "an input of the corpus or the regressions fails (see above)"
fi
ran=$(grep -c '^Executed ' replay.log)
[[ $ran == "${#inputs[@]}" ]] || { tail -n 20 replay.log >&2; fail "replayed $ran of ${#inputs[@]} inputs"; }

[[ $seconds -gt 0 ]] || exit 0
dirs=("$work/corpus" "$corpus")
[[ -d $regressions ]] && dirs+=("$regressions")
dictopt=()
[[ -f $dict ]] && dictopt=(-dict="$dict")
# Mutations stay small (fast) even though some regressions are large; those are replayed whole.
maxlen=8192
[[ $name == fbxfix ]] && maxlen=32768
# Reproducible in CI: a fixed seed (SYLVA_FUZZ_SEED=0 draws one) makes the mutations the same
# sequence on every machine, so a slower machine runs a prefix of what passed here. The obstacle
# harness is also capped in runs: Debian's Assimp is not instrumented, so its out-of-bounds writes
# show only later, if at all (docs/reliability.md, findings 12 and 24), and a CI run must not
# depend on the machine's speed; scripts/fuzz.sh keeps fuzzing it at random.
runs=-1
[[ $name == obstacle ]] && runs=${SYLVA_FUZZ_OBSTACLE_RUNS:-3000}
echo "run-fuzzer: $name: fuzzing for $seconds s"
if ! "$bin" "${limits[@]}" "${dictopt[@]}" -max_len=$maxlen -max_total_time="$seconds" \
  -seed="${SYLVA_FUZZ_SEED:-1}" -runs="$runs" -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "${dirs[@]}" >fuzz.log 2>&1; then
  tail -n 80 fuzz.log >&2
  found=$(ls "$work/artifacts" 2>/dev/null | head -n 1)
  fail "fuzzing found a failure${found:+: $work/artifacts/$found}; fix it and add the input to tests/fuzz/regressions/$name/"
fi
grep -E '^(#[0-9]+ +DONE|Done |stat::number_of_executed_units|stat::peak_rss_mb)' fuzz.log || true
echo "run-fuzzer: $name: passed"
