#!/usr/bin/env bash
# Installs what is missing, builds Release and opens the editor on the demo project (its forest
# with the wall and the boulder it grows around).
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
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)"

BIN=build/release/app
DEMO_SPECIES=presets/ternary-tree.json
DEMO_PROJECT=resources/demo/forest.sylva
if [[ $headless == 1 ]]; then
  out=out/demo
  mkdir -p "$out"
  "$BIN/cli/sylva-cli" forest resources/demo/forest.sylva -o "$out/forest.obj" --stats > "$out/forest.stats.json"
  echo "generated $out/forest.obj: $(grep -o '"trees":[0-9]*' "$out/forest.stats.json" | head -1 | cut -d: -f2) trees," \
       "$(grep -o '"triangles":[0-9]*' "$out/forest.stats.json" | head -1 | cut -d: -f2) triangles"
  "$BIN/cli/sylva-cli" forest resources/demo/stand.sylva -o "$out/stand.glb" --stats > "$out/stand.stats.json"
  echo "generated $out/stand.glb: self-organizing trees grown together"
  "$BIN/cli/sylva-cli" tree "$DEMO_SPECIES" -o "$out/ternary-tree.obj" --stats > "$out/ternary-tree.stats.json"
  echo "generated $out/ternary-tree.obj"
  "$BIN/cli/sylva-cli" stats resources/demo/forest.sylva > "$out/forest.carbon.txt"
  echo "biomass and CO2 of the demo forest: $out/forest.carbon.txt"
  echo "Demo files are in $(pwd)/$out (materials in *.mtl, textures in $out/textures)"
  echo "Python: PYTHONPATH=$(pwd)/build/release/python /usr/bin/python3 -c 'import sylva' (docs/python.md)"
else
  exec "$BIN/editor/sylva" "$DEMO_PROJECT"
fi
