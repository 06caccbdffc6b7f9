#!/usr/bin/env bash
# End-to-end tests of sylva-cli: exit statuses, messages, outputs, no partial files.
# usage: cli_tests.sh <case> <sylva-cli> <tests/data> <scratch folder>
set -uo pipefail
case_name=$1 CLI=$2 DATA=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1

fail() { echo "FAIL [$case_name]: $*" >&2; exit 1; }
# run_cli <expected status> args... : captures stdout/stderr into out.txt/err.txt
run_cli() {
  local want=$1; shift
  "$CLI" "$@" >out.txt 2>err.txt
  local got=$?
  [[ $got == "$want" ]] || { cat err.txt >&2; fail "exit status $got, expected $want for: $*"; }
}

case $case_name in
expand_algae)
  run_cli 0 expand "$DATA/lsystem/algae.lsys"
  [[ $(cat out.txt) == "abaababaabaab" ]] || fail "got '$(cat out.txt)'"
  run_cli 0 expand "$DATA/lsystem/algae.lsys" -n 3
  [[ $(cat out.txt) == "abaab" ]] || fail "-n 3 gave '$(cat out.txt)'" ;;
expand_parametric)
  # Hand-derived: B(2)A(4,4) -> B(1)B(4)A(1,0) -> B(0)B(3)A(2,1)
  run_cli 0 expand "$DATA/lsystem/parametric.lsys"
  [[ $(cat out.txt) == "B(0)B(3)A(2,1)" ]] || fail "got '$(cat out.txt)'" ;;
expand_seed_determinism)
  run_cli 0 expand "$DATA/lsystem/stochastic.lsys" --seed 5; cp out.txt a.txt
  run_cli 0 expand "$DATA/lsystem/stochastic.lsys" --seed 5
  cmp -s a.txt out.txt || fail "same seed gave different strings"
  differs=0
  for s in 6 7 8 9; do
    run_cli 0 expand "$DATA/lsystem/stochastic.lsys" --seed $s
    cmp -s a.txt out.txt || differs=1
  done
  [[ $differs == 1 ]] || fail "five seeds gave the same string" ;;
tree_obj_and_stats)
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o bush.obj --stats
  [[ -s bush.obj ]] || fail "no OBJ written"
  grep -q '^o ' bush.obj || fail "OBJ has no object"
  grep -q '^vn ' bush.obj || fail "OBJ has no normals"
  for key in symbols segments leaves vertices triangles height timings_ms expand interpret mesh write; do
    grep -q "\"$key\"" out.txt || fail "stats lack $key: $(cat out.txt)"
  done
  # 3 generations of F -> F[+F]F[-F]F: 5^3 = 125 F's, i.e. 125 segments
  grep -q '"segments":125[,}]' out.txt || fail "expected 125 segments: $(cat out.txt)"
  v=$(grep -c '^v ' bush.obj); f=$(grep -c '^f ' bush.obj)
  grep -q "\"vertices\":$v[,}]" out.txt || fail "stats vertices differ from OBJ's $v"
  grep -q "\"triangles\":$f[,}]" out.txt || fail "stats triangles differ from OBJ's $f" ;;
tree_species_json)
  mkdir -p sp && cp "$DATA/lsystem/bush.lsys" sp/
  cat > sp/bush.json <<'JSON'
{ "format": "sylva-species", "format_version": 1, "name": "Test bush",
  "graph": { "nodes": [
      { "id": "grow", "type": "lsystem", "params": { "grammar_file": "bush.lsys" } },
      { "id": "mesh", "type": "tube_mesh", "inputs": ["grow"], "params": { "resolution": 5 } } ],
    "output": "mesh" } }
JSON
  run_cli 0 tree sp/bush.json -o t.obj --stats
  grep -q '^o Test_bush' t.obj || fail "object not named after the species"
  grep -q '"segments":125[,}]' out.txt || fail "$(cat out.txt)" ;;
tree_set_override)
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o a.obj --stats --set grow.generations=2
  grep -q '"segments":25[,}]' out.txt || fail "--set grow.generations=2: $(cat out.txt)"
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o a.obj --stats -n 1
  grep -q '"segments":5[,}]' out.txt || fail "-n 1: $(cat out.txt)" ;;
tree_determinism)
  run_cli 0 tree "$DATA/lsystem/stochastic.lsys" -o a.obj --seed 11
  run_cli 0 tree "$DATA/lsystem/stochastic.lsys" -o b.obj --seed 11
  cmp -s a.obj b.obj || fail "same seed, different OBJ"
  OMP_NUM_THREADS=1 "$CLI" tree "$DATA/lsystem/stochastic.lsys" -o c.obj --seed 11 || fail "1 thread"
  OMP_NUM_THREADS=2 "$CLI" tree "$DATA/lsystem/stochastic.lsys" -o d.obj --seed 11 || fail "2 threads"
  cmp -s c.obj d.obj || fail "1 and 2 threads differ"
  cmp -s a.obj c.obj || fail "thread count changed the output" ;;
bad_syntax_reports_position)
  run_cli 1 expand "$DATA/lsystem/bad-syntax.lsys"
  grep -Eq "bad-syntax.lsys:3:[0-9]+: error: .*" err.txt || fail "message: $(cat err.txt)"
  [[ $(wc -l < err.txt) -ge 1 ]] || fail "no message" ;;
bad_usage_exit_2)
  run_cli 2 frobnicate
  run_cli 2 tree "$DATA/lsystem/bush.lsys"
  grep -q -- "-o" err.txt || fail "no hint about -o: $(cat err.txt)"
  run_cli 2 expand "$DATA/lsystem/algae.lsys" --bogus
  run_cli 2 expand "$DATA/lsystem/algae.lsys" -n lots
  run_cli 2 ;;
runaway_limit)
  run_cli 1 expand "$DATA/lsystem/runaway.lsys"
  grep -qi "generation" err.txt || fail "limit message does not name the generation: $(cat err.txt)"
  grep -qi "limit" err.txt || fail "message does not mention the limit: $(cat err.txt)" ;;
no_partial_output)
  run_cli 1 tree "$DATA/lsystem/runaway.lsys" -o big.obj
  [[ ! -e big.obj ]] || fail "a failed run left big.obj"
  echo "precious" > keep.obj
  run_cli 1 tree "$DATA/lsystem/bad-syntax.lsys" -o keep.obj
  [[ $(cat keep.obj) == precious ]] || fail "a failed run changed an existing file"
  [[ $(ls -A | grep -c '\.tmp') == 0 ]] || fail "temporary files left: $(ls -A)" ;;
bad_param_range)
  run_cli 1 tree "$DATA/lsystem/bush.lsys" -o a.obj --set mesh.resolution=1
  grep -q "resolution" err.txt || fail "$(cat err.txt)"
  grep -q "\[" err.txt || fail "message lacks the allowed range: $(cat err.txt)"
  run_cli 1 tree "$DATA/lsystem/bush.lsys" -o a.obj --set nosuchnode.x=1
  grep -q "nosuchnode" err.txt || fail "$(cat err.txt)"
  [[ ! -e a.obj ]] || fail "output written despite errors" ;;
missing_file)
  run_cli 1 tree does-not-exist.json -o a.obj
  grep -q "does-not-exist.json" err.txt || fail "$(cat err.txt)" ;;
*) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
