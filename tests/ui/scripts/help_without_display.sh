#!/bin/sh
# `sylva --help`, `-h` and `--version` answer on a machine with no display (issue 21): usage
# and every editor option on stdout, status 0; an unknown option next to --help is an error
# (status 1), still without a display. Usage: help_without_display.sh <sylva>
set -u
sylva=$1
unset DISPLAY WAYLAND_DISPLAY QT_QPA_PLATFORM
out=$(mktemp) err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
fail() { echo "FAIL: $*" >&2; echo "stdout:" >&2; cat "$out" >&2; echo "stderr:" >&2; cat "$err" >&2; exit 1; }
for form in --help -h; do
  "$sylva" $form >"$out" 2>"$err" || fail "sylva $form exited $?"
  grep -q "^Usage: .*sylva \[options\] \[species.json|project.sylva\]" "$out" || fail "sylva $form: no usage line"
  for opt in --script --screenshot --size --color-by --restore --discard-autosave --version; do
    grep -q -- "$opt" "$out" || fail "sylva $form does not list $opt"
  done
  [ ! -s "$err" ] || fail "sylva $form wrote to stderr"
done
"$sylva" --version >"$out" 2>"$err" || fail "sylva --version exited $?"
grep -q "^Sylva [0-9]" "$out" || fail "sylva --version"
"$sylva" --bogus --help >"$out" 2>"$err"
status=$?
[ "$status" -eq 1 ] || fail "sylva --bogus --help exited $status, expected 1"
grep -q "bogus" "$err" || fail "sylva --bogus --help does not name the unknown option"
echo "sylva --help, -h, --version: ok without a display"
