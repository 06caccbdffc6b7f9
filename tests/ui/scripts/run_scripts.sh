#!/bin/sh
# Runs the editor's Python scripting tests: `sylva --script` on the demo project (a copy, so
# saving never touches the repository's file), exit statuses, a SIGTERM in a wait, and a
# SIGKILL after scripted edits followed by a start that restores them.
# Usage: run_scripts.sh <sylva> <source dir> <out>
set -eu
SYLVA=$1
SRC=$2
OUT=$3
HERE=$(dirname "$0")
rm -rf "$OUT"
mkdir -p "$OUT/config"
export SYLVA_TEST_OUT="$OUT"
export XDG_CONFIG_HOME="$OUT/config" # settings and the autosave copy stay in the test folder
export SYLVA_PRESETS_DIR="$SRC/presets"
DEMO="$SRC/resources/demo/alder-reference.sylva"
fail() { echo "FAIL: $*" >&2; exit 1; }

echo "-- api_edits.py"
"$SYLVA" --discard-autosave --script "$HERE/api_edits.py" "$DEMO" || fail "api_edits.py"

echo "-- api_branches.py (hand edits of single branches)"
"$SYLVA" --discard-autosave --script "$HERE/api_branches.py" "$DEMO" || fail "api_branches.py"

echo "-- api_species.py"
"$SYLVA" --discard-autosave --script "$HERE/api_species.py" "$DEMO" || fail "api_species.py"

echo "-- api_wind.py"
"$SYLVA" --discard-autosave --script "$HERE/api_wind.py" "$DEMO" || fail "api_wind.py"

echo "-- view_wind.py (View > Wind, the wind clock)"
"$SYLVA" --discard-autosave --script "$HERE/view_wind.py" "$DEMO" || fail "view_wind.py"

echo "-- project_layout.py (win.project() before the first layout)"
"$SYLVA" --discard-autosave --script "$HERE/project_layout.py" "$DEMO" || fail "project_layout.py"

echo "-- real_input.py (xdotool)"
"$SYLVA" --discard-autosave --script "$HERE/real_input.py" "$DEMO" || fail "real_input.py"

echo "-- branch_tool.py (the Branch tool, xdotool)"
"$SYLVA" --discard-autosave --script "$HERE/branch_tool.py" "$DEMO" || fail "branch_tool.py"

echo "-- seasons.py (the viewport's leaves in four seasons)"
"$SYLVA" --discard-autosave --script "$HERE/seasons.py" "$DEMO" || fail "seasons.py"

echo "-- exit_status.py"
status=0
"$SYLVA" --script "$HERE/exit_status.py" || status=$?
[ "$status" -eq 3 ] || fail "sylva.quit(3) exited with $status"

echo "-- raises.py"
status=0
"$SYLVA" --script "$HERE/raises.py" "$DEMO" 2>"$OUT/raises.err" || status=$?
[ "$status" -eq 1 ] || fail "a raised exception exited with $status"
grep -q "Traceback" "$OUT/raises.err" || fail "no traceback on stderr"
grep -q "ValueError: unknown species 'no-such-species'" "$OUT/raises.err" || fail "no message"

echo "-- interrupted_wait.py (SIGTERM while the script waits)"
"$SYLVA" --discard-autosave --script "$HERE/interrupted_wait.py" >"$OUT/wait.out" 2>"$OUT/wait.err" &
pid=$!
tries=0
until grep -q waiting "$OUT/wait.out"; do
  kill -0 "$pid" 2>/dev/null || fail "the editor ended before the script's wait"
  tries=$((tries + 1))
  [ "$tries" -lt 600 ] || { kill -KILL "$pid"; fail "the script never reached its wait"; }
  sleep 0.2
done
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
[ "$status" -eq 143 ] || fail "SIGTERM in sylva.wait exited with $status"
grep -q "KeyboardInterrupt: stopped by SIGTERM" "$OUT/wait.err" || fail "no KeyboardInterrupt"
grep -q 'interrupted_wait.py", line 9, in keep_the_window_open' "$OUT/wait.err" ||
  fail "the traceback does not name the wait"
! grep -q "not interrupted" "$OUT/wait.out" || fail "the script went on after SIGTERM"

echo "-- crash_after_edits.py (SIGKILL)"
status=0
"$SYLVA" --discard-autosave --script "$HERE/crash_after_edits.py" "$DEMO" || status=$?
[ "$status" -eq 137 ] || fail "the editor was not killed (status $status)"
ls "$OUT/config/Sylva/Sylva/recovery/autosave.sylva" >/dev/null || fail "no autosave copy after the crash"
echo "-- check_restored.py (--restore)"
"$SYLVA" --restore --script "$HERE/check_restored.py" || fail "check_restored.py"
[ ! -e "$OUT/config/Sylva/Sylva/recovery/autosave.sylva" ] || fail "the copy outlived a normal exit"

echo "-- one_edit_then_crash.py (the first edit alone, SIGKILL)"
status=0
"$SYLVA" --discard-autosave --script "$HERE/one_edit_then_crash.py" "$DEMO" || status=$?
[ "$status" -eq 137 ] || fail "the editor was not killed (status $status)"
ls "$OUT/config/Sylva/Sylva/recovery/autosave.sylva" >/dev/null ||
  fail "the first edit after opening was not autosaved"
echo "-- check_one_edit_restored.py (--restore)"
"$SYLVA" --restore --script "$HERE/check_one_edit_restored.py" || fail "check_one_edit_restored.py"
echo "script tests: 11 passed, 0 failed"
