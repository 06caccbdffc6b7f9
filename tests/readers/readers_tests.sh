#!/usr/bin/env bash
# Sylva's exports read by programs nobody here wrote (tests/readers/package.json, installed by
# scripts/install-readers.sh): the Khronos glTF-Validator and three.js's GLTFLoader under Node,
# tinyusdz for USD.
# Exit 77 (ctest: skipped) with a message when node or the packages are missing.
# usage: readers_tests.sh <case> <sylva-cli> <tests/data> <scratch folder>
set -uo pipefail
case_name=$1 CLI=$2 DATA=$3 WORK=$4
READERS=$(cd "$(dirname "$0")" && pwd)
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1

fail() { echo "FAIL [$case_name]: $*" >&2; exit 1; }
command -v node >/dev/null || { echo "SKIP: node not installed (scripts/install-deps.sh)"; exit 77; }
[[ $case_name == tinyusdz_* || ( -d "$READERS/node_modules/gltf-validator" && -d "$READERS/node_modules/three" ) ]] ||
  { echo "SKIP: tests/readers/node_modules missing (run scripts/install-readers.sh)"; exit 77; }
run_cli() {
  "$CLI" "$@" >out.txt 2>err.txt || fail "sylva-cli $* failed: $(cat err.txt)"
}
validate() {
  node "$READERS/validate.mjs" "$1" > report.txt 2>&1 || fail "$1: $(cat report.txt)"
  grep -q ": 0 errors" report.txt || fail "$1: $(tail -1 report.txt)"
  tail -1 report.txt
}
stat_of() { python3 -c "import json,sys; print(json.load(open('stats.json')).get(sys.argv[1], ''))" "$1"; }

case $case_name in
gltf_validator_forest)
  # A forest with instanced variants, unique trees and library textures: glb and gltf+bin.
  run_cli forest "$DATA/projects/small.sylva" -o forest.glb
  validate forest.glb
  run_cli forest "$DATA/projects/small.sylva" -o text/forest.gltf
  [[ -s text/forest.bin && -s text/textures/bark.png ]] || fail "no .bin or textures beside the .gltf: $(ls -R text)"
  validate text/forest.gltf ;;
gltf_validator_tree)
  run_cli tree "$DATA/../../presets/english-oak.json" --seed 2 -o oak.glb
  validate oak.glb
  run_cli tree "$DATA/lsystem/bush.lsys" -o bush.glb
  validate bush.glb ;;
three_forest_instances)
  # three.js builds one InstancedMesh per instanced node: their counts sum to the instanced
  # trees, every tree is an instance or a unique node, and each instance's id is listed.
  run_cli forest "$DATA/projects/small.sylva" -o forest.glb --stats
  cp out.txt stats.json
  node "$READERS/count-instances.mjs" forest.glb > three.json 2> three.err || fail "three.js: $(cat three.err)"
  cat three.json
  python3 - <<'PY' || fail "three.js counts do not match the forest: $(cat three.json) vs $(cat stats.json)"
import json, struct
three = json.load(open("three.json"))
stats = json.load(open("stats.json"))
data = open("forest.glb", "rb").read()
doc = json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])
nodes = doc["nodes"]
unique_nodes = sum(1 for n in nodes if "sylva_id" in n.get("extras", {}))
ids = [i for n in nodes for i in n.get("extras", {}).get("sylva_ids", [])]
assert three["mismatched"] == 0, three
assert three["instances"] == len(ids) == three["ids"], (three, len(ids))
assert three["instances"] > 0, "nothing instanced"
assert three["instances"] + unique_nodes == stats["trees"], (three, unique_nodes, stats["trees"])
if "instanced" in stats:
    assert three["instances"] == stats["instanced"], (three, stats["instanced"])
    assert unique_nodes == stats["unique"], (unique_nodes, stats["unique"])
all_ids = ids + [n["extras"]["sylva_id"] for n in nodes if "sylva_id" in n.get("extras", {})]
assert len(set(all_ids)) == len(all_ids) == stats["trees"], "ids are not one per tree"
PY
  ;;
three_leaf_tints)
  # Leaf tints (issue #33, Mesh::colors as COLOR_0): three.js reads them as a normalized
  # colour attribute its material multiplies by, varied on the leaves, white on the bark.
  run_cli tree "$DATA/../../presets/english-oak.json" --seed 2 -o oak.glb
  node "$READERS/leaf-tints.mjs" oak.glb > three.json 2> three.err || fail "three.js: $(cat three.err)"
  cat three.json
  python3 - <<'PY' || fail "three.js does not read the leaf tints: $(cat three.json)"
import json
meshes = json.load(open("three.json"))["meshes"]
leaf = [m for m in meshes if "leaf" in m["material"]]
bark = [m for m in meshes if "leaf" not in m["material"]]
assert leaf and bark, meshes
for m in meshes:
    assert m["color"] and m["itemSize"] == 4 and m["normalized"] and m["vertexColors"], m
assert all(m["distinct"] > 100 and 0.2 < m["minGreen"] < 0.95 for m in leaf), leaf
assert all(m["distinct"] == 1 and m["minGreen"] == 1 for m in bark), bark
PY
  ;;
tinyusdz_leaf_tints)
  # The same oak as USD: tinyusdz parses displayColor on the leaf mesh, one colour a card face.
  [[ -d "$READERS/node_modules/tinyusdz" ]] || { echo "SKIP: tinyusdz missing (run scripts/install-readers.sh)"; exit 77; }
  run_cli tree "$DATA/../../presets/english-oak.json" --seed 2 -o oak.usda
  node "$READERS/usd-tints.mjs" oak.usda > tinyusdz.json 2> tinyusdz.err || fail "tinyusdz: $(cat tinyusdz.err)"
  cat tinyusdz.json
  python3 - <<'PY' || fail "tinyusdz does not read the leaf tints: $(cat tinyusdz.json)"
import json
t = json.load(open("tinyusdz.json"))
assert t["all"] >= 2, t
assert len(t["meshes"]) == 1 and "leaf" in t["meshes"][0]["name"], t
m = t["meshes"][0]
assert m["interpolation"] == "uniform" and m["colors"] == m["faces"] > 1000, m
PY
  ;;
wind_glb)
  # Wind (docs/wind.md): 0 validator errors, three.js plays the clip and the twig tip moves
  # more than the trunk's base, and two exports are byte-identical.
  run_cli tree "$DATA/../../presets/english-oak.json" --seed 2 -o oak.glb --wind
  validate oak.glb
  # (the same name in another folder: the GLB names its Pivot Painter textures after itself)
  mkdir -p again
  run_cli tree "$DATA/../../presets/english-oak.json" --seed 2 -o again/oak.glb --wind
  for f in oak.glb oak_pivot_index.exr oak_xaxis_extent.png; do
    cmp -s "$f" "again/$f" || fail "two wind exports differ: $f"
  done
  node "$READERS/wind-motion.mjs" oak.glb > three.json 2> three.err || fail "three.js: $(cat three.err)"
  cat three.json
  python3 - <<'PY' || fail "three.js: the wind clip does not move the tree as it should: $(cat three.json)"
import json
m = json.load(open("three.json"))
assert abs(m["duration"] - 4.0) < 1e-6, m
assert 2 <= m["joints"] <= 64, m
assert m["tip"] > 0.02, m
assert m["tip"] > 5 * m["base"], m
PY
  run_cli forest "$DATA/projects/small.sylva" -o forest.glb --wind --bones 16 --clip-length 2
  validate forest.glb ;;
tinyusdz_forest|tinyusdz_tiles)
  # tinyusdz parses the stage (and composes a farm run's root over its tiles): its prim and
  # array counts are the forest's statistics (instancers' arrays all as long as protoIndices,
  # one id per instance, one tree_<id> Xform per unique tree, K variants per species).
  [[ -d "$READERS/node_modules/tinyusdz" ]] || { echo "SKIP: tinyusdz missing (run scripts/install-readers.sh)"; exit 77; }
  run_cli forest "$DATA/projects/small.sylva" -o forest.usda --stats
  cp out.txt stats.json
  layer=forest.usda
  if [[ $case_name == tinyusdz_tiles ]]; then
    for i in 1 2 3 4; do run_cli forest "$DATA/projects/small.sylva" -o tiles/part_$i.usda --tile $i/4; done
    run_cli compose root.usda tiles/part_*.usda
    layer=root.usda
  fi
  node "$READERS/usd-counts.mjs" "$layer" > tinyusdz.json 2> tinyusdz.err || fail "tinyusdz: $(cat tinyusdz.err)"
  cat tinyusdz.json
  python3 - "$case_name" <<'PY' || fail "tinyusdz counts do not match the forest: $(cat tinyusdz.json) vs $(cat stats.json)"
import json, sys
t = json.load(open("tinyusdz.json"))
s = json.load(open("stats.json"))
tiles = 4 if sys.argv[1] == "tinyusdz_tiles" else 1
assert t["layers"] == 1 + (tiles if tiles > 1 else 0), t
assert t["mismatched"] == [], t
assert t["instances"] == t["ids"] == s["instanced"] > 0, (t, s["instanced"])
assert t["trees"] == s["unique"], (t, s["unique"])
assert t["instances"] + t["trees"] == s["trees"], (t, s["trees"])
assert t["variantPrims"] == s["variants"] == s["usd"]["prototypes"], (t, s["variants"])
assert t["materials"] == s["usd"]["materials"], t
if tiles == 1:
    assert t["instancers"] == s["usd"]["instancers"], t
    assert t["renderTrees"] == s["unique"], t
    assert t["renderMeshes"] == s["usd"]["meshes"], (t, s["usd"])
else:
    assert t["instancers"] >= s["usd"]["instancers"], t
PY
  ;;
gltf_validator_lods)
  # The game LOD chain (issue #32): MSFT_lod levels, the impostor card and its three maps.
  run_cli lods "$DATA/../../presets/alder.json" -o lods --json --no-obj --no-fbx
  validate lods/alder_LODs.glb ;;
three_lod_levels)
  # three.js loads every level MSFT_lod names, with the triangles the description reports.
  run_cli lods "$DATA/../../presets/alder.json" -o lods --json --no-obj --no-fbx
  node "$READERS/lod-levels.mjs" lods/alder_LODs.glb > three.json 2> three.err || fail "three.js: $(cat three.err)"
  cat three.json
  python3 - <<'PY' || fail "three.js levels do not match the description: $(cat three.json)"
import json
three = json.load(open("three.json"))
desc = json.load(open("lods/alder_lods.json"))
levels = three["levels"]
assert len(levels) == len(desc["levels"]) + 1, levels
for got, want in zip(levels, desc["levels"]):
    assert got["name"] == want["name"] and got["triangles"] == want["triangles"], (got, want)
assert levels[-1]["name"] == desc["impostor"]["name"] and levels[-1]["triangles"] == 2
assert levels[-1]["material"] == desc["impostor"]["name"], levels[-1]
tris = [l["triangles"] for l in levels]
assert all(a > b for a, b in zip(tris, tris[1:])), tris
cov = three["coverage"]
assert len(cov) == len(levels) and cov[-1] == 0, cov
assert all(a > b for a, b in zip(cov, cov[1:])), cov
PY
  ;;
tinyusdz_lods)
  # The LOD chain's USD stage (issue #32): the root prim's variant set "lod" holds LOD0..LODn and
  # the impostor; tinyusdz composes each selection into that level's meshes alone, with the
  # triangles --json reports, every mesh bound, the impostor's card on its colour and normal maps.
  [[ -d "$READERS/node_modules/tinyusdz" ]] || { echo "SKIP: tinyusdz missing (run scripts/install-readers.sh)"; exit 77; }
  run_cli lods "$DATA/../../presets/silver-birch.json" -o lods --json --no-obj --no-fbx --no-glb
  cp out.txt desc.json
  [[ -s lods/silver-birch_lods.usda && -s lods/textures/bark.png ]] || fail "no stage or textures: $(ls -R lods)"
  node "$READERS/usd-lods.mjs" lods/silver-birch_lods.usda > tinyusdz.json 2> tinyusdz.err || fail "tinyusdz: $(cat tinyusdz.err)"
  cat tinyusdz.json
  python3 - <<'PY' || fail "tinyusdz's variants do not match the description: $(cat tinyusdz.json)"
import json
t = json.load(open("tinyusdz.json"))
d = json.load(open("desc.json"))
assert d["files"]["usd"] == "silver-birch_lods.usda", d["files"]
assert t["declared"] and t["selection"] == "LOD0", t
names = ["LOD%d" % i for i in range(len(d["levels"]))] + ["impostor"]
assert list(t["variants"]) == names, list(t["variants"])
for name, level in zip(names, d["levels"]):
    v = t["variants"][name]
    assert v["triangles"] == level["triangles"], (name, v["triangles"], level["triangles"])
    assert v["meshes"] == 2 and v["bound"] == 2, (name, v)  # bark and leaf
    assert all(p.startswith("/silver_birch/%s/" % name) for p in v["paths"]), v["paths"]
    assert v["composedVariantSets"] == 0 and v["otherLevels"] == [], v
imp = t["variants"]["impostor"]
assert imp["meshes"] == 1 and imp["triangles"] == 2 and imp["bound"] == 1, imp
assert imp["colorMaps"] == [d["impostor"]["maps"]["color"]], imp
assert imp["normalMaps"] == [d["impostor"]["maps"]["normal"]], imp
tris = [t["variants"][n]["triangles"] for n in names]
assert all(a > b for a, b in zip(tris, tris[1:])), tris
PY
  ;;
*) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
