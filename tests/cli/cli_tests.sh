#!/usr/bin/env bash
# End-to-end tests of sylva-cli: exit statuses, messages, outputs, no partial files.
# usage: cli_tests.sh <case> <sylva-cli> <tests/data> <scratch folder>
set -uo pipefail
case_name=$1 CLI=$2 DATA=$3 WORK=$4
SRC=$(cd "$(dirname "$0")" && pwd)
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
omp_passive_waiting)
  # OpenMP threads wait without spinning (GOMP_SPINCOUNT 0) unless the caller set a policy,
  # which is kept (libgomp prints its settings at start; the last print is the run's).
  unset OMP_WAIT_POLICY SYLVA_NO_REEXEC
  OMP_DISPLAY_ENV=verbose run_cli 0 help
  spin=$(grep "GOMP_SPINCOUNT = " err.txt | tail -1)
  [[ $spin == *"'0'"* ]] || fail "not passive: $spin"
  OMP_DISPLAY_ENV=verbose OMP_WAIT_POLICY=active run_cli 0 help
  [[ $(grep -c "GOMP_SPINCOUNT = " err.txt) == 1 ]] || fail "started again with a policy set"
  grep -q "GOMP_SPINCOUNT = '30000000000'" err.txt || fail "the caller's ACTIVE was not kept" ;;
nodes_reference)
  # The node metadata is the one source: docs/species.md carries exactly what it prints.
  run_cli 0 nodes --markdown && cp out.txt "$WORK/nodes.md"
  docs="$DATA/../../docs/species.md"
  sed -n '/<!-- nodes:begin/,/<!-- nodes:end/p' "$docs" | sed '1d;$d' > "$WORK/docs.md"
  diff -u "$WORK/docs.md" "$WORK/nodes.md" || fail "docs/species.md differs from 'sylva-cli nodes --markdown' (regenerate it)"
  for t in lsystem space_colonization self_organizing adapt tube_mesh leaves; do
    grep -q "^### \`$t\`" "$WORK/nodes.md" || fail "no $t in the listing"
  done
  run_cli 0 nodes space_colonization && cp out.txt "$WORK/sc.txt"
  grep -q "influence_distance.*d_i" "$WORK/sc.txt" || fail "space_colonization lacks d_i"
  run_cli 0 nodes --json && cp out.txt "$WORK/nodes.json"
  python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert {n['name'] for n in d} >= {'lsystem','adapt'}" "$WORK/nodes.json" || fail "nodes --json"
  run_cli 2 nodes no_such_type
  grep -q "known: adapt" err.txt || fail "unknown type message: $(cat err.txt)"
  ;;
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
tree_self_organizing_stats)
  # A self-organizing species reports its metamers, those shed and those starving now.
  run_cli 0 tree "$DATA/../../presets/so-shrub.json" -o s.obj --stats --set grow.cycles=8
  for key in internodes cycles shed starved; do
    grep -q "\"$key\":[0-9]" out.txt || fail "stats lack $key: $(cat out.txt)"
  done
  grep -q '"cycles":8[,}]' out.txt || fail "--set grow.cycles=8: $(cat out.txt)"
  n=$(grep -o '"internodes":[0-9]*' out.txt | cut -d: -f2)
  st=$(grep -o '"starved":[0-9]*' out.txt | cut -d: -f2)
  seg=$(grep -o '"segments":[0-9]*' out.txt | cut -d: -f2)
  (( n > 100 && st <= n && seg == n )) || fail "internodes $n, starved $st, segments $seg"
  # An L-system tree has none of them.
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o b.obj --stats
  ! grep -q '"starved"' out.txt || fail "an L-system reports starved metamers" ;;
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
  # Same file name in four folders: the OBJ names its MTL after itself.
  mkdir -p a b c d
  run_cli 0 tree "$DATA/lsystem/stochastic.lsys" -o a/t.obj --seed 11
  run_cli 0 tree "$DATA/lsystem/stochastic.lsys" -o b/t.obj --seed 11
  cmp -s a/t.obj b/t.obj || fail "same seed, different OBJ"
  OMP_NUM_THREADS=1 "$CLI" tree "$DATA/lsystem/stochastic.lsys" -o c/t.obj --seed 11 || fail "1 thread"
  OMP_NUM_THREADS=2 "$CLI" tree "$DATA/lsystem/stochastic.lsys" -o d/t.obj --seed 11 || fail "2 threads"
  cmp -s c/t.obj d/t.obj || fail "1 and 2 threads differ"
  cmp -s a/t.obj c/t.obj || fail "thread count changed the output"
  run_cli 0 tree "$DATA/lsystem/stochastic.lsys" -o b/t.obj --seed 12
  ! cmp -s a/t.obj b/t.obj || fail "another seed gave the same tree" ;;
leaf_tints_threads_identical)
  # Leaf colour variation (issue #33): the library trees' tinted cards, in summer and autumn,
  # give the same GLB, USD and OBJ bytes on 1 and 2 threads; the colours are there.
  lib="$DATA/../../resources/demo/library.sylva"
  for t in 1 2; do
    mkdir -p "t$t"
    for f in lib.glb lib.usda lib.obj; do
      OMP_NUM_THREADS=$t "$CLI" forest "$lib" -o "t$t/$f" >/dev/null 2>err.txt || fail "$t threads, $f: $(cat err.txt)"
    done
    OMP_NUM_THREADS=$t "$CLI" tree "$DATA/../../presets/norway-maple.json" --season autumn -o "t$t/maple.glb" >/dev/null 2>err.txt || fail "$t threads, maple: $(cat err.txt)"
  done
  for f in lib.glb lib.usda lib.obj maple.glb; do
    cmp -s "t1/$f" "t2/$f" || fail "1 and 2 threads differ: $f"
  done
  grep -q "COLOR_0" t1/maple.glb || fail "no COLOR_0 in the maple"
  [[ $(grep -c "primvars:displayColor" t1/lib.usda) -ge 10 ]] || fail "displayColor on fewer than 10 species"
  grep -qE "^v [^ ]+ [^ ]+ [^ ]+ 0\.[0-9]+ " t1/lib.obj || fail "no tinted OBJ vertex" ;;
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
help_every_command)
  # sylva-cli <command> --help (and -h, and help <command>) prints that command's help on
  # stdout and exits 0, wherever --help stands and whatever else is on the line.
  for cmd in expand tree forest stats lods nodes; do
    for form in "$cmd --help" "$cmd -h" "help $cmd" "$cmd $DATA/lsystem/bush.lsys --bogus --help"; do
      # shellcheck disable=SC2086
      run_cli 0 $form
      head -n 1 out.txt | grep -q "^usage: sylva-cli $cmd " || fail "'$form' printed: $(cat out.txt)"
      grep -q -- "-h, --help" out.txt || fail "'$form' does not list --help"
      [[ ! -s err.txt ]] || fail "'$form' wrote to stderr: $(cat err.txt)"
    done
  done
  for form in "help --help" "help -h"; do # help is a command too
    # shellcheck disable=SC2086
    run_cli 0 $form
    head -n 1 out.txt | grep -q "^usage: sylva-cli help " || fail "'$form' printed: $(cat out.txt)"
    grep -q -- "-h, --help" out.txt || fail "'$form' does not list --help"
  done
  run_cli 0 forest --help
  for opt in --output --camera --threads --tile --stats --no-lod --no-adapt --no-neighbours \
    --no-instancing --instance-tables --naive-placement --full-precision --fsync; do
    grep -q -- "$opt" out.txt || fail "forest --help does not list $opt"
  done
  run_cli 0 tree --help
  for opt in --output --generations --seed --set --stats --compact --fsync; do
    grep -q -- "$opt" out.txt || fail "tree --help does not list $opt"
  done
  # -h as the value of an option is that value, not a request for help.
  run_cli 2 tree -o -h
  grep -q "usage: sylva-cli tree" err.txt || fail "no usage line: $(cat err.txt)"
  run_cli 0 --help
  grep -q "help \[command\]" out.txt || fail "general help: $(cat out.txt)"
  run_cli 2 help frobnicate ;;
runaway_limit)
  run_cli 1 expand "$DATA/lsystem/runaway.lsys"
  grep -qi "generation" err.txt || fail "limit message does not name the generation: $(cat err.txt)"
  grep -qi "limit" err.txt || fail "message does not mention the limit: $(cat err.txt)" ;;
time_limit)
  run_cli 1 expand "$DATA/lsystem/slow.lsys" --time-limit 1
  grep -q "took more than its time limit of 1 s (stopped in generation" err.txt ||
    fail "no time limit message: $(cat err.txt)"
  grep -q "sylva-cli expand --time-limit" err.txt || fail "does not say how to raise it"
  run_cli 2 expand "$DATA/lsystem/slow.lsys" --time-limit 0 ;;
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
tree_glb_export)
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o bush.glb
  [[ $(head -c 4 bush.glb) == glTF ]] || fail "not a binary glTF"
  if command -v assimp >/dev/null; then
    assimp info bush.glb > info.txt 2>&1 || fail "assimp cannot read the GLB: $(cat info.txt)"
    grep -qi "meshes" info.txt || fail "$(cat info.txt)"
  fi
  run_cli 0 tree "$DATA/lsystem/bush.lsys" -o bush.obj
  [[ -s bush.mtl ]] || fail "no MTL beside the OBJ"
  grep -q '^mtllib bush.mtl' bush.obj || fail "OBJ does not reference its MTL"
  grep -q '^usemtl bark' bush.obj || fail "no bark material in use" ;;
species_textures_exported)
  # A library species: its own bark and leaf cluster atlas PNGs beside the OBJ (named by the MTL), inside the
  # GLB and the FBX (read back by Assimp's command-line tool, which nobody here wrote).
  oak="$DATA/../../presets/english-oak.json"
  run_cli 0 tree "$oak" -o oak.obj --seed 2
  for kind in bark leafcluster; do
    grep -q "^map_Kd textures/english-oak_$kind.png" oak.mtl || fail "MTL lacks the $kind texture"
    grep -q "^usemtl english-oak_$kind" oak.obj || fail "OBJ does not use english-oak_$kind"
    [[ -s textures/english-oak_$kind.png ]] || fail "textures/english-oak_$kind.png missing"
    [[ $(head -c 4 textures/english-oak_$kind.png | tail -c 3) == PNG ]] || fail "not a PNG"
  done
  grep -q "^map_d textures/english-oak_leafcluster.png" oak.mtl || fail "leaf cut-out (map_d) missing"
  # Normal and roughness maps: named by the MTL (norm for Assimp, map_Bump for Blender) and
  # copied beside it (the cluster atlas has its own, drawn like the leaf's).
  for kind in bark leafcluster; do
    for key in norm map_Bump; do
      grep -q "^$key textures/english-oak_${kind}_normal.png" oak.mtl || fail "MTL lacks $key of $kind"
    done
    grep -q "^map_Pr textures/english-oak_${kind}_roughness.png" oak.mtl || fail "MTL lacks map_Pr of $kind"
    [[ -s textures/english-oak_${kind}_normal.png ]] || fail "${kind} normal map not copied"
  done
  if command -v assimp >/dev/null; then
    assimp info oak.obj > info.txt 2>&1 || fail "assimp cannot read oak.obj"
    [[ $(grep -c '| Normals\]' info.txt) -ge 2 ]] || fail "assimp reads no normal maps from the OBJ"
    # GLB: colour, normal and roughness maps of bark and leaf; FBX: colour and normal maps
    # (FBX's classic material has no roughness slot Assimp writes).
    for f in oak.glb:6 oak.fbx:4; do
      run_cli 0 tree "$oak" -o "${f%:*}" --seed 2
      assimp info "${f%:*}" > info.txt 2>&1 || fail "assimp cannot read $f: $(cat info.txt)"
      grep -Eq "Textures \(embed\.\): +${f#*:}$" info.txt || fail "$f: $(grep -i textures info.txt)"
      [[ $(grep -c '| Normals\]' info.txt) -ge 2 ]] || fail "assimp reads no normal maps from $f"
    done
  fi ;;
tree_season)
  # Seasons: winter leaves a broadleaf bare and a conifer as it was; autumn uses the species'
  # autumn cluster atlas; a name that is no season is a usage error.
  oak="$DATA/../../presets/english-oak.json" pine="$DATA/../../presets/scots-pine.json"
  run_cli 0 tree "$oak" -o summer.obj --seed 2
  run_cli 0 tree "$oak" -o winter.obj --seed 2 --season winter
  grep -q "^usemtl english-oak_leaf" summer.obj || fail "summer oak has no leaves"
  ! grep -q "^usemtl english-oak_leaf" winter.obj || fail "winter oak kept its leaves"
  run_cli 0 tree "$oak" -o autumn.obj --seed 2 --season autumn
  grep -q "^usemtl english-oak_leafcluster_autumn" autumn.obj || fail "autumn oak lacks autumn leaves"
  [[ -s textures/english-oak_leafcluster_autumn.png ]] || fail "autumn leaf texture not copied"
  run_cli 0 tree "$pine" -o pine-summer.obj --seed 2
  run_cli 0 tree "$pine" -o pine-winter.obj --seed 2 --season winter
  cmp -s <(grep -v '^mtllib' pine-summer.obj) <(grep -v '^mtllib' pine-winter.obj) ||
    fail "a conifer changed in winter"
  run_cli 2 tree "$oak" -o x.obj --season monsoon
  grep -q "spring, summer, autumn or winter" err.txt || fail "$(cat err.txt)" ;;
forest_season)
  # A project's season, a tree's own season over it, and --season over both.
  presets="$(cd "$DATA/../../presets" && pwd)"
  write_project() { # $1: the project's season key ("" for none), $2: the first oak's season key
    cat > seasons.sylva <<EOF
{ "format": "sylva-project", "format_version": 1, "seed": 3, $1
  "species": [ { "name": "oak", "file": "$presets/english-oak.json" },
               { "name": "pine", "file": "$presets/scots-pine.json" } ],
  "instances": [
    { "species": "oak", "position": [0, 0, 0], "seed": 1 $2 },
    { "species": "oak", "position": [30, 0, 0], "seed": 2 },
    { "species": "pine", "position": [-30, 0, 0], "seed": 3 } ] }
EOF
  }
  write_project "" ""
  run_cli 0 forest seasons.sylva -o summer.obj --no-lod
  [[ $(grep -c '^usemtl english-oak_leafcluster$' summer.obj) == 2 ]] || fail "summer oaks lack leaves"
  write_project '"season": "autumn",' ', "season": "winter"'
  run_cli 0 forest seasons.sylva -o autumn.obj --no-lod
  [[ $(grep -c '^usemtl english-oak_leafcluster_autumn$' autumn.obj) == 1 ]] || fail "the autumn oak"
  ! grep -q '^usemtl english-oak_leafcluster$' autumn.obj || fail "a summer oak in an autumn project"
  # The pine is the same in every season.
  pine() { awk '/^o /{on=($2 ~ /^pine_/)} on && /^(v|f) /' "$1"; }
  cmp -s <(pine summer.obj) <(pine autumn.obj) || fail "the pine changed in autumn"
  run_cli 0 forest seasons.sylva -o winter.obj --no-lod --season winter
  ! grep -q '^usemtl english-oak_leaf' winter.obj || fail "--season winter left leaves on an oak"
  grep -q '^usemtl scots-pine_leaf' winter.obj || fail "the pine lost its needles"
  run_cli 2 forest seasons.sylva -o x.obj --season monsoon
  grep -q "spring, summer, autumn or winter" err.txt || fail "$(cat err.txt)"
  write_project '"season": "monsoon",' ""
  run_cli 1 forest seasons.sylva -o x.obj
  grep -q "season" err.txt || fail "a bad project season: $(cat err.txt)" ;;
forest_obj_and_stats)
  run_cli 0 forest "$DATA/projects/small.sylva" -o forest.obj --stats
  n=$(grep -c '^o ' forest.obj)
  [[ $n == 41 ]] || fail "expected 41 tree objects (1 hand-placed + 40), got $n"
  grep -q '^o bush_1$' forest.obj || fail "hand-placed tree (id 1) missing"
  for key in trees vertices triangles colliding_trees instanced unique variants metrics co2_kg timings_ms place write total; do
    grep -q "\"$key\"" out.txt || fail "stats lack $key: $(cat out.txt)"
  done
  grep -q '"trees":41,' out.txt || fail "$(cat out.txt)"
  # the hand-placed bush stands 0.6 m from the wall: at least it collides
  grep -q '"colliding_trees":[1-9]' out.txt || fail "no tree touched the wall: $(cat out.txt)" ;;
forest_threads_identical)
  mkdir -p one two
  run_cli 0 forest "$DATA/projects/small.sylva" -o one/f.obj --threads 1
  run_cli 0 forest "$DATA/projects/small.sylva" -o two/f.obj --threads 2
  cmp -s one/f.obj two/f.obj || fail "1 and 2 threads give different forests"
  run_cli 2 forest "$DATA/projects/small.sylva" -o three/f.obj --threads 0
  grep -q "threads must be a whole number in \[1, 1024\], got '0'" err.txt ||
    fail "no --threads limit message: $(cat err.txt)" ;;
forest_tiles_union)
  run_cli 0 forest "$DATA/projects/small.sylva" -o whole.obj
  : > tiles.txt
  for i in 1 2 3 4; do
    run_cli 0 forest "$DATA/projects/small.sylva" -o tile$i.obj --tile $i/4
    # per object: its name and every line of it; the forest's compact OBJ counts face
    # indices back within each object, so a tree's text does not depend on the trees before it
    awk '/^o /{name=$2} /^(v|vt|vn|f|usemtl) /{print name, $0}' tile$i.obj >> tiles.txt
  done
  awk '/^o /{name=$2} /^(v|vt|vn|f|usemtl) /{print name, $0}' whole.obj | sort > whole.txt
  sort tiles.txt > union.txt
  cmp -s whole.txt union.txt || fail "the union of 4 tiles differs from the whole forest"
  run_cli 2 forest "$DATA/projects/small.sylva" -o x.obj --tile 5/4
  run_cli 2 forest "$DATA/projects/small.sylva" -o x.obj --tile zero ;;
forest_obj_precision)
  # default: compact (0.1 mm positions, relative face indices); --full-precision: micrometres
  # and absolute indices; the same trees and faces either way
  run_cli 0 forest "$DATA/projects/small.sylva" -o c.obj
  run_cli 0 forest "$DATA/projects/small.sylva" -o full.obj --full-precision
  grep -q '^f -[0-9]' c.obj || fail "compact OBJ should use relative face indices"
  grep -q '^f -' full.obj && fail "full precision OBJ should use absolute face indices"
  awk '/^v /{split($2,a,"."); if (length(a[2]) > 4) bad=1} END{exit bad}' c.obj ||
    fail "compact positions have more than 4 decimals"
  awk '/^v /{split($2,a,"."); if (length(a[2]) == 6) six=1} END{exit !six}' full.obj ||
    fail "full precision positions never have 6 decimals"
  [[ $(grep -c '^f ' c.obj) == $(grep -c '^f ' full.obj) ]] || fail "face counts differ"
  [[ $(grep -c '^o ' c.obj) == $(grep -c '^o ' full.obj) ]] || fail "object counts differ"
  (( $(stat -c %s c.obj) < $(stat -c %s full.obj) )) || fail "compact is not smaller" ;;
forest_reference_scene)
  run_cli 0 forest "$DATA/projects/reference-scene.json" -o ref.obj --stats
  grep -q '"trees":8,' out.txt || fail "$(cat out.txt)" ;;
forest_bad_project)
  printf '{"format":"sylva-project","format_version":1,"species":[{"name":"a","file":"missing.json"}],"domains":[{"shape":"rectangle","min":[0,0],"max":[5,5],"counts":{"a":3}}]}' > bad.sylva
  run_cli 1 forest bad.sylva -o f.obj
  grep -q "missing.json" err.txt || fail "$(cat err.txt)"
  [[ ! -e f.obj ]] || fail "partial output"
  printf '{"format":"sylva-project","format_version":1,"species":[{"name":"a","file":"%s"}],"obstacles":[{"file":"nowhere.obj"}]}' "$DATA/lsystem/bush.lsys" > bad2.sylva
  run_cli 1 forest bad2.sylva -o f.obj
  grep -q "nowhere.obj" err.txt || fail "$(cat err.txt)"
  printf '{"format":"sylva-project","format_version":1,"seed":' > trunc.sylva
  run_cli 1 forest trunc.sylva -o f.obj
  grep -q "trunc.sylva:1:" err.txt || fail "$(cat err.txt)"
  [[ ! -e f.obj ]] || fail "partial output" ;;
stats_species)
  run_cli 0 stats "$DATA/lsystem/bush.lsys" --json
  for key in mean_height_m mean_dbh_m wood_volume_m3 dry_biomass_kg carbon_kg co2_kg chave_agb_kg; do
    grep -q "\"$key\"" out.txt || fail "stats lack $key: $(cat out.txt)"
  done
  run_cli 0 stats "$DATA/lsystem/bush.lsys"
  grep -q "CO2 equivalent (kg)" out.txt || fail "table lacks units: $(cat out.txt)" ;;
stats_project)
  run_cli 0 stats "$DATA/projects/small.sylva" --json
  grep -q '"trees":41' out.txt || fail "$(cat out.txt)" ;;
lods_chain)
  run_cli 0 lods "$DATA/lsystem/bush.lsys" -o lods --json
  for i in 0 1 2 3; do [[ -s lods/bush_LOD$i.obj ]] || fail "missing bush_LOD$i.obj: $(ls lods)"; done
  for f in bush_LODs.glb bush_LODs.fbx bush_lods.json bush_lods.usda bush_impostor_color.png \
      bush_impostor_normal.png bush_impostor_depth.png; do
    [[ -s lods/$f ]] || fail "missing $f: $(ls lods)"
  done
  cmp -s out.txt lods/bush_lods.json || fail "--json is not the description written"
  # triangle counts never grow from level to level, and LOD0 to LOD1 really shrinks
  tris=$(grep -o '"triangles": [0-9]*' out.txt | cut -d' ' -f2 | tr '\n' ' ')
  read -r t0 t1 t2 t3 <<< "$tris"
  (( t0 > t1 && t1 >= t2 && t2 >= t3 )) || fail "triangles do not decrease: $tris"
  # the atlas: 8 x 8 views of 256 px
  [[ $(python3 -c "import struct;d=open('lods/bush_impostor_color.png','rb').read(24);print(struct.unpack('>II',d[16:24]))") == "(2048, 2048)" ]] ||
    fail "impostor atlas is not 2048 x 2048"
  # the same bytes on one thread and on two (Assimp's FBX carries its creation time: not compared)
  OMP_NUM_THREADS=1 run_cli 0 lods "$DATA/lsystem/bush.lsys" -o one --no-obj --no-fbx
  OMP_NUM_THREADS=2 run_cli 0 lods "$DATA/lsystem/bush.lsys" -o two --no-obj --no-fbx
  for f in bush_LODs.glb bush_lods.json bush_lods.usda bush_impostor_color.png \
      bush_impostor_normal.png bush_impostor_depth.png; do
    cmp -s one/$f two/$f || fail "$f differs between 1 and 2 threads"
  done
  run_cli 0 lods "$DATA/lsystem/bush.lsys" -o small --no-obj --no-fbx --no-glb \
    --budgets 1,0.5 --impostor-grid 4 --impostor-cell 32 --octahedral
  grep -q '"layout": "octahedral"' small/bush_lods.json || fail "no octahedral layout"
  grep -q '"atlas_pixels": 128' small/bush_lods.json || fail "$(cat small/bush_lods.json)"
  [[ ! -e small/bush_LODs.glb && ! -e small/bush_LOD0.obj ]] || fail "--no-glb/--no-obj ignored"
  run_cli 0 lods "$DATA/lsystem/bush.lsys" -o nousd --no-obj --no-fbx --no-glb --no-usd \
    --impostor-cell 16
  [[ ! -e nousd/bush_lods.usda && -s nousd/bush_lods.json ]] || fail "--no-usd ignored: $(ls nousd)"
  run_cli 1 lods "$DATA/lsystem/bush.lsys" -o bad --budgets 1,0.5,0.7
  grep -q "LOD2 budget must be above 0 and below the one before" err.txt || fail "$(cat err.txt)"
  run_cli 1 lods "$DATA/lsystem/bush.lsys" -o bad --budgets 1,x
  grep -q "'x' is not a number" err.txt || fail "$(cat err.txt)"
  if command -v assimp >/dev/null; then
    # Assimp reads the FBX's levels as the _LOD<i> nodes
    assimp info lods/bush_LODs.fbx > info.txt 2>&1 || fail "assimp cannot read the FBX: $(cat info.txt)"
    # siblings right under the root (Unity builds its LOD Group from _LOD<i> children of one parent)
    for i in 0 1 2 3; do grep -Eq "^(├╴|└╴)bush_LOD$i \(mesh" info.txt || fail "FBX lacks bush_LOD$i under the root: $(tail info.txt)"; done
  fi ;;
lods_dropped_levels)
  # The date palm has 456 triangles: its 12 % and 4 % budgets (54 and 18) are under the coarsest
  # mesh the camera LOD makes before the palm is 4 px high. They are dropped and reported (not
  # written as over-budget copies of LOD1), and the impostor follows LOD1.
  run_cli 0 lods "$DATA/../../presets/date-palm.json" -o palm --json --no-obj --no-fbx --no-usd \
    --impostor-cell 16
  python3 - <<'PY' || fail "$(cat out.txt)"
import json
d = json.load(open("out.txt"))
names = [l["name"] for l in d["levels"]]
assert names == ["date-palm_LOD0", "date-palm_LOD1"], names
assert [x["budget"] for x in d["dropped_levels"]] == [0.12, 0.04], d["dropped_levels"]
for x in d["dropped_levels"]:
    assert x["coarsest_triangles"] > x["budget_triangles"], x
    assert "4 px" in x["reason"], x
for l in d["levels"]:
    assert l["budget_met"] and l["triangles"] <= l["budget"] * d["levels"][0]["triangles"], l
    assert l["silhouette_iou"] >= 0.9, l
assert d["impostor"]["switch_distance_m"] >= 1.5 * d["levels"][1]["switch_distance_m"] - 1e-6
PY
  run_cli 0 lods "$DATA/../../presets/date-palm.json" -o table --no-obj --no-fbx --no-usd \
    --no-glb --impostor-cell 16
  [[ $(grep -c "dropped: budget below the coarsest mesh" out.txt) == 2 ]] || fail "$(cat out.txt)"
  # --min-silhouette: 0 checks nothing (every level with the default 0.5-px clusters), out of
  # range is an error naming the range
  run_cli 0 lods "$DATA/lsystem/bush.lsys" -o nocheck --json --no-obj --no-fbx --no-usd --no-glb \
    --impostor-cell 16 --min-silhouette 0
  [[ $(grep -c '"leaf_cluster_px": 0.5' out.txt) == 3 ]] || fail "$(cat out.txt)"
  run_cli 1 lods "$DATA/lsystem/bush.lsys" -o bad --min-silhouette 1.5
  grep -q "from 0 to 1" err.txt || fail "$(cat err.txt)"
  ;;
lods_fbx_blender)
  # Blender imports the FBX chain's levels with the triangles (as polygons) the JSON reports.
  command -v blender >/dev/null || { echo "SKIP: blender not installed"; exit 77; }
  run_cli 0 lods "$DATA/lsystem/bush.lsys" -o lods --no-obj --no-glb
  cat > import.py <<'PY'
import bpy, json, sys
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.fbx(filepath=sys.argv[-1])
meshes = [o for o in bpy.data.objects if o.type == "MESH"]
assert len({o.parent for o in meshes}) == 1, [(o.name, o.parent) for o in meshes]  # siblings
print("LEVELS " + json.dumps({o.name: len(o.data.polygons) for o in meshes}))
PY
  blender -b --python import.py -- lods/bush_LODs.fbx > blender.txt 2>&1 || fail "blender: $(tail blender.txt)"
  python3 - <<'PY' || fail "Blender's levels differ: $(grep LEVELS blender.txt)"
import json
got = json.loads(open("blender.txt").read().split("LEVELS ", 1)[1].splitlines()[0])
want = {l["name"]: l["triangles"] for l in json.load(open("lods/bush_lods.json"))["levels"]}
assert got == want, (got, want)
PY
  ;;
forest_species_adapt_node)
  # A species with its own adapt node reacts to the scene's wall (the bush at x=0.5 m touches
  # the 0.2 m thick wall at x=0; the one at x=30 m does not).
  run_cli 0 forest "$DATA/projects/adapt.sylva" -o f.obj --stats
  grep -q '"colliding_trees":1,' out.txt || fail "$(cat out.txt)"
  run_cli 0 forest "$DATA/projects/adapt.sylva" -o g.obj --stats --no-adapt
  grep -q '"colliding_trees":0,' out.txt || fail "--no-adapt still adapted: $(cat out.txt)" ;;
forest_interrupt)
  # Ctrl-C during a long run (1,000 trees, every one grown: ~3 s on 2 cores): exit 130, no
  # output, no temporary left behind.
  "$CLI" forest "$DATA/../../resources/demo/bench-1000.sylva" -o big.obj --no-instancing \
    >out.txt 2>err.txt &
  pid=$!
  sleep 1
  kill -INT $pid
  wait $pid
  got=$?
  [[ $got == 130 ]] || fail "exit status $got after SIGINT, expected 130: $(cat err.txt)"
  grep -q "interrupted" err.txt || fail "no message: $(cat err.txt)"
  [[ ! -e big.obj ]] || fail "a half-written big.obj is left"
  [[ $(ls -A | grep -c 'tmp') == 0 ]] || fail "temporary files left: $(ls -A)" ;;
forest_terrain)
  # Trees stand where a ray down meets the terrain y = 2 + 0.1 x: every tree's lowest vertex
  # lies on the slope (within the root's radius), never at y = 0.
  run_cli 0 forest "$DATA/projects/terrain.sylva" -o t.obj --stats --no-lod
  grep -q '"trees":12,' out.txt || fail "$(cat out.txt)"
  awk '/^o /{if (name!="") print name, lo, x; name=$2; lo=1e9} /^v /{if ($3<lo){lo=$3; x=$2}} END{print name, lo, x}' t.obj > low.txt
  awk '{ground=2+0.1*$3; d=$2-ground; if (d<0) d=-d; if (d>0.2) {print "off the slope:", $0; bad=1}} END{exit bad}' low.txt \
    || fail "a tree does not stand on the terrain: $(cat low.txt)" ;;
forest_instancing)
  # Issue 30: free domain trees are instances of their species' K variants (8 by default);
  # --stats reports instanced + unique = trees; OBJ writes every tree, named by its id.
  json_num() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" out.txt "$1"; }
  run_cli 0 forest "$DATA/projects/small.sylva" -o f.obj --stats
  trees=$(json_num trees) inst=$(json_num instanced) uniq=$(json_num unique) vars=$(json_num variants)
  (( inst + uniq == trees )) || fail "instanced $inst + unique $uniq != trees $trees"
  (( inst > 0 && uniq > 0 )) || fail "expected both kinds: $(cat out.txt)"
  [[ $vars == 16 ]] || fail "2 species x 8 variants, got $vars"
  [[ $(grep -c '^o ' f.obj) == "$trees" ]] || fail "OBJ objects != trees"
  [[ $(grep '^o ' f.obj | sort -u | wc -l) == "$trees" ]] || fail "object names repeat"
  # domain trees: domain id 1 x 10^9 + slot
  [[ $(grep -Ec '^o (bush|shrub)_10000000[0-9]{2}$' f.obj) == $((trees - 1)) ]] ||
    fail "domain tree names: $(grep '^o ' f.obj | head -3)"
  run_cli 0 forest "$DATA/projects/small.sylva" -o g.obj --stats --no-instancing
  [[ $(json_num instanced) == 0 && $(json_num unique) == "$trees" && $(json_num variants) == 0 ]] ||
    fail "--no-instancing: $(cat out.txt)"
  run_cli 0 stats "$DATA/projects/small.sylva" --json
  [[ $(json_num instanced) == "$inst" ]] || fail "stats and forest disagree: $(cat out.txt)"
  python3 -c "
import json,sys
d=json.load(open('out.txt'))
t=d['per_tree']
assert len(t)==$trees and t[0]['id']==1 and t[0]['variant']==-1, t[0]
assert sum(1 for x in t if x['variant']>=0)==$inst
assert all(x['name'].endswith('_'+str(x['id'])) for x in t)
" || fail "per_tree ids/variants"
  run_cli 0 stats "$DATA/projects/small.sylva"
  grep -Eq "^instanced trees +$inst$" out.txt || fail "table: $(cat out.txt)" ;;
forest_move_one_tree)
  # Moving the hand-placed tree 30 m regrows only the trees it stood or stands near: every
  # other tree's OBJ object is byte for byte the same.
  python3 - "$DATA/projects/small.sylva" <<'PY' || fail "cannot write the moved project"
import json, os, sys
src = sys.argv[1]
p = json.load(open(src))
base = os.path.dirname(os.path.abspath(src))
for s in p["species"]: s["file"] = os.path.join(base, s["file"])
for o in p["obstacles"]: o["file"] = os.path.join(base, o["file"])
json.dump(p, open("before.sylva", "w"))
p["instances"][0]["position"][0] += 30
json.dump(p, open("after.sylva", "w"))
PY
  run_cli 0 forest before.sylva -o before.obj
  run_cli 0 forest after.sylva -o after.obj
  python3 - <<'PY' > moved.txt || fail "$(cat moved.txt)"
import math
def objects(path):
    out, name = {}, None
    for line in open(path):
        if line.startswith("o "): name = line.split()[1]; out[name] = []
        elif name and line[:2] in ("v ", "f ", "vt", "vn", "us"): out[name].append(line)
    return out
a, b = objects("before.obj"), objects("after.obj")
assert set(a) == set(b), "tree ids changed: %s" % (set(a) ^ set(b))
changed = [n for n in a if a[n] != b[n]]
def centre(lines):
    v = [list(map(float, l.split()[1:4])) for l in lines if l.startswith("v ")]
    return (sum(p[0] for p in v) / len(v), sum(p[2] for p in v) / len(v))
for n in changed:
    if n == "bush_1": continue
    x, z = centre(a[n])
    d = min(math.hypot(x - 0, z - 0.6), math.hypot(x - 30, z - 0.6))
    assert d < 8, "%s at (%.1f, %.1f) changed, %.1f m from the moved tree" % (n, x, z, d)
print("changed %d of %d" % (len(changed), len(a)))
assert "bush_1" in changed and len(changed) < len(a) / 2, changed
PY
  cat moved.txt ;;
forest_glb_threads_identical)
  # The instanced GLB and the text glTF with its .bin are byte-identical on 1 and 2 threads.
  mkdir -p one two
  for ext in glb gltf; do
    run_cli 0 forest "$DATA/projects/small.sylva" -o one/f.$ext --threads 1
    run_cli 0 forest "$DATA/projects/small.sylva" -o two/f.$ext --threads 2
    cmp -s one/f.$ext two/f.$ext || fail "1 and 2 threads give different f.$ext"
  done
  cmp -s one/f.bin two/f.bin || fail "1 and 2 threads give different f.bin"
  grep -q EXT_mesh_gpu_instancing one/f.gltf || fail "no instancing in the glTF" ;;
forest_glb_sigterm)
  # SIGTERM (what Slurm sends) while a 10,000-tree GLB is being written: the writer stops at its
  # next array, exit 130, no file and no temporary left. The run is stopped once the GLB's
  # temporary exists (the variants are written), or after 20 s at most.
  "$CLI" forest "$DATA/../../resources/demo/bench-10000.sylva" -o big.glb --threads 2 >out.txt 2>err.txt &
  pid=$!
  for _ in $(seq 200); do
    compgen -G '.big.glb.bin.tmp*' >/dev/null && break
    sleep 0.1
  done
  compgen -G '.big.glb.bin.tmp*' >/dev/null || fail "the GLB's temporary never appeared: $(ls -A)"
  sleep 1
  kill -TERM $pid
  # A hang guard, not a timing: a cancelled run that has not exited after 20 s is stuck.
  for _ in $(seq 200); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
  kill -0 $pid 2>/dev/null && { kill -KILL $pid; fail "still running 20 s after SIGTERM"; }
  wait $pid
  got=$?
  [[ $got == 130 ]] || fail "exit status $got after SIGTERM, expected 130: $(cat err.txt)"
  grep -q "interrupted" err.txt || fail "no message: $(cat err.txt)"
  [[ ! -e big.glb ]] || fail "a partial big.glb is left"
  [[ $(ls -A | grep -c 'tmp') == 0 ]] || fail "temporary files left: $(ls -A)" ;;
forest_usd)
  # A USD stage: stage metadata, every tree once (unique meshes or instances), normals and
  # uvs with their interpolation, materials with the textures copied beside; byte-identical
  # on 1 and 2 threads.
  run_cli 0 forest "$DATA/projects/small.sylva" -o one.usda --threads 1 --stats
  cp out.txt stats.json
  run_cli 0 forest "$DATA/projects/small.sylva" -o two.usda --threads 2
  cmp -s one.usda two.usda || fail "1 and 2 threads wrote different USD"
  head -1 one.usda | grep -qx '#usda 1.0' || fail "no #usda header"
  for meta in 'defaultPrim = "Forest"' 'metersPerUnit = 1' 'upAxis = "Y"'; do
    grep -qF "$meta" one.usda || fail "no $meta"
  done
  grep -q 'interpolation = "vertex"' one.usda || fail "no primvar interpolation"
  grep -q 'texCoord2f\[\] primvars:st = ' one.usda || fail "no primvars:st"
  grep -q 'normal3f\[\] normals = ' one.usda || fail "no normals"
  grep -q 'uniform token info:id = "UsdPreviewSurface"' one.usda || fail "no UsdPreviewSurface"
  grep -q 'asset inputs:file = @textures/bark.png@' one.usda || fail "no bark texture"
  [[ -s textures/bark.png ]] || fail "textures not copied"
  trees=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['trees'])" stats.json)
  read -r listed unique instanced < <(python3 "$SRC/usda_trees.py" one.usda --summary)
  [[ $listed == "$trees" ]] || fail "the stage holds $listed trees, the forest $trees"
  python3 - stats.json "$unique" "$instanced" <<'PY' || fail "usd stats disagree with the stage"
import json, sys
d = json.load(open(sys.argv[1]))
u = d["usd"]
assert u["unique_trees"] == int(sys.argv[2]) == d["unique"], (u, d["unique"])
assert u["instances"] == int(sys.argv[3]) == d["instanced"], (u, d["instanced"])
assert d["instanced"] > 0 and u["prototypes"] == d["variants"], d
PY
  [[ $(ls -A | grep -c tmp) == 0 ]] || fail "temporary files left: $(ls -A)" ;;
forest_usd_tiles_compose)
  # Four tile layers composed by a root layer hold the single run's forest, tree for tree
  # (ids, species, transforms as written); compose refuses incomplete or foreign tile sets.
  run_cli 0 forest "$DATA/projects/small.sylva" -o single.usda
  for i in 1 2 3 4; do run_cli 0 forest "$DATA/projects/small.sylva" -o tiles/part_$i.usda --tile $i/4; done
  run_cli 0 compose root.usda tiles/part_4.usda tiles/part_2.usda tiles/part_1.usda tiles/part_3.usda
  grep -q '@tiles/part_1.usda@' root.usda || fail "root does not name tile 1 relative to it"
  grep -qF 'upAxis = "Y"' root.usda || fail "root has no upAxis"
  python3 "$SRC/usda_trees.py" single.usda > single.txt || fail "cannot list single"
  python3 "$SRC/usda_trees.py" root.usda > composed.txt || fail "cannot list composed"
  [[ -s single.txt ]] || fail "no trees listed"
  diff -u single.txt composed.txt || fail "the composed stage differs from the single run"
  run_cli 1 compose bad.usda tiles/part_1.usda tiles/part_2.usda
  grep -q "missing of 4: 3, 4" err.txt || fail "missing tiles: $(cat err.txt)"
  [[ ! -e bad.usda ]] || fail "a root was written for an incomplete set"
  run_cli 0 forest "$DATA/projects/small.sylva" -o other/part_3.usda --tile 3/4 --no-adapt
  run_cli 1 compose bad.usda tiles/part_1.usda tiles/part_2.usda other/part_3.usda tiles/part_4.usda
  grep -q "of another run" err.txt || fail "foreign tile: $(cat err.txt)"
  run_cli 1 compose bad.usda single.usda tiles/part_1.usda
  run_cli 2 compose root.usda ;;
forest_sigterm_fbx|forest_sigterm_usd|forest_sigterm_obj)
  # SIGTERM (Slurm's stop) at a known phase: inside Assimp's FBX exporter 0.7 s after the trees
  # are built (it ran to the end before), and mid-build for the streaming writers. Exit 130,
  # no output, no temporary left.
  ext=${case_name##*_}; [[ $ext == usd ]] && ext=usda
  # The FBX case grows every tree uniquely (--no-instancing): instanced forests export so fast
  # that the signal could arrive after the file is written.
  at="trees 100 0.7"; extra=(--no-instancing); [[ $ext != fbx ]] && { at="trees 40 0"; extra=(); }
  python3 "$SRC/signal_during.py" $at SIGTERM "$CLI" forest "$DATA/../../resources/demo/bench-1000.sylva" \
    -o big.$ext "${extra[@]}" >took.txt 2>err.txt
  got=$?
  [[ $got == 130 ]] || fail "exit status $got after SIGTERM, expected 130: $(cat err.txt)"
  grep -q "interrupted" err.txt || fail "no message: $(cat err.txt)"
  echo "stopped $(cat took.txt) s after SIGTERM"
  [[ ! -e big.$ext ]] || fail "a half-written big.$ext is left"
  [[ $(ls -A | grep -v -e '^took.txt$' -e '^err.txt$' -e '^out.txt$' | wc -l) == 0 ]] || fail "files left: $(ls -A)" ;;
*) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
