#!/bin/sh
# The artist's-day test (issue #40): artists_day.py through `sylva --script` with its own
# settings folder, output folder and the repository's presets. Usage: artists_day.sh <sylva>
# <source dir> <out>
set -eu
SYLVA=$1
SRC=$2
OUT=$3
rm -rf "$OUT"
mkdir -p "$OUT/config"
export SYLVA_TEST_OUT="$OUT"
export SYLVA_SOURCE_DIR="$SRC"
export XDG_CONFIG_HOME="$OUT/config"
export SYLVA_PRESETS_DIR="$SRC/presets"
exec "$SYLVA" --discard-autosave --script "$(dirname "$0")/artists_day.py"
