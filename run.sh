#!/usr/bin/env bash
# Installs what is missing, builds Release and opens the editor on the demo.
# With --headless (or without a display) it generates the demo with sylva-cli instead and
# prints where the files went.
set -euo pipefail
cd "$(dirname "$0")"
headless=0
for a in "$@"; do
  case "$a" in
    --headless) headless=1 ;;
    -h|--help) echo "usage: ./run.sh [--headless]"; exit 0 ;;
    *) echo "run.sh: unknown option $a" >&2; exit 2 ;;
  esac
done
if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" ]]; then headless=1; fi

./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"

BIN=build/release/app
DEMO_SPECIES=presets/ternary-tree.json
if [[ $headless == 1 ]]; then
  out=out/demo
  mkdir -p "$out"
  for species in "$DEMO_SPECIES" presets/alder.json; do
    name=$(basename "$species" .json)
    "$BIN/cli/sylva-cli" tree "$species" -o "$out/$name.obj" --stats > "$out/$name.stats.json"
    echo "generated $out/$name.obj ($(grep -o '"triangles":[0-9]*' "$out/$name.stats.json"))"
  done
  echo "Demo files are in $(pwd)/$out"
else
  exec "$BIN/editor/sylva" "$DEMO_SPECIES"
fi
