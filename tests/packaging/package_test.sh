#!/usr/bin/env bash
# Builds the Debian package with CPack from a finished build, unpacks it into a scratch root
# and runs what it installed from there: sylva-cli on a preset, `import sylva` (Debian's
# python3) finding its presets and textures in the package, the add-on and desktop files.
# Usage: package_test.sh <build folder> <work folder>
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

start=$(date +%s)
cpack --config "$build/CPackConfig.cmake" -B "$work/pkg" > cpack.log 2>&1 || { cat cpack.log; fail "cpack"; }
deb=$(ls "$work"/pkg/*.deb)
echo "package: $(basename "$deb"), $(du -h "$deb" | cut -f1), built in $(( $(date +%s) - start )) s"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for dep in python3 python3-numpy qt6-qpa-plugins libqt6core6 libassimp5 libembree3-3; do
  [[ $depends == *"$dep"* ]] || fail "Depends lacks $dep"
done

dpkg-deb -x "$deb" root
R=$work/root/usr
for f in bin/sylva bin/sylva-cli share/applications/sylva.desktop \
         share/icons/hicolor/scalable/apps/sylva.svg share/sylva/presets/ternary-tree.json \
         share/sylva/presets/lsystem/ternary-tree.lsys share/sylva/resources/textures/bark.png \
         share/sylva/resources/demo/forest.sylva share/sylva/blender/sylva_blender/__init__.py; do
  [[ -f $R/$f ]] || fail "the package lacks /usr/$f"
done
module=$(ls "$R"/lib/python3/dist-packages/sylva.cpython-*.so) || fail "no Python module"
if command -v desktop-file-validate >/dev/null; then desktop-file-validate "$R/share/applications/sylva.desktop"; fi

# The installed CLI, from the scratch root: a preset tree, textures copied beside it.
mkdir -p out
"$R/bin/sylva-cli" tree "$R/share/sylva/presets/abop-1.24a.json" --seed 3 -o out/cli/tree.obj --stats > out/stats.json
grep -q '"vertices":[1-9]' out/stats.json || fail "sylva-cli tree: $(cat out/stats.json)"
[[ -f out/cli/textures/bark.png ]] || fail "the installed sylva-cli did not find its textures"

# The installed module with Debian's python3: same tree, same bytes; its data from the package.
PYTHONPATH=$R/lib/python3/dist-packages /usr/bin/python3 - "$R" <<'PY'
import os, sys
import sylva
root = sys.argv[1]
assert sylva.__file__.startswith(root), sylva.__file__
assert sylva.presets_dir() == os.path.join(root, "share/sylva/presets"), sylva.presets_dir()
assert sylva.resources_dir() == os.path.join(root, "share/sylva/resources"), sylva.resources_dir()
tree = sylva.grow(os.path.join(sylva.presets_dir(), "abop-1.24a.json"), seed=3)
tree.export("out/py/tree.obj")
assert os.path.exists("out/py/textures/bark.png")
print("import sylva:", sylva.__version__, "from", sylva.__file__)
PY
cmp out/cli/tree.obj out/py/tree.obj || fail "module and CLI trees differ"

# Dependencies resolvable on this Debian (simulated install; needs apt).
if command -v apt-get >/dev/null; then
  apt-get install -s -q "$deb" > apt.log 2>&1 || { cat apt.log; fail "apt-get cannot install the package"; }
  echo "apt-get -s: $(grep -c '^Inst' apt.log) package(s) to install"
fi
echo "package test passed in $(( $(date +%s) - start )) s"
