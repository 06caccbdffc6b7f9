"""sylva projects and forests: the same trees and bytes as `sylva-cli forest`, obstacles and a
ground from arrays, progress, the GIL released, Ctrl-C."""
import json
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import sylva
from conftest import read_obj_mesh


def test_forest_equals_cli(data, cli, tmp_path):
    project = data / "projects" / "small.sylva"
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    (tmp_path / "stream").mkdir()
    r = cli("forest", project, "-o", tmp_path / "cli" / "forest.obj", "--stats")
    cli_stats = json.loads(r.stdout)

    forest = sylva.load_project(project).build_forest()
    assert len(forest) == cli_stats["trees"] == 41
    for key in ("trees", "vertices", "triangles", "colliding_trees", "pruned_nodes",
                "obstacle_triangles", "shortfall", "instanced", "unique", "variants"):
        assert forest.stats[key] == cli_stats[key], key
    assert forest.stats["metrics"]["co2_kg"] == pytest.approx(cli_stats["metrics"]["co2_kg"])
    assert sum(t.mesh.vertex_count for t in forest.trees) == cli_stats["vertices"]
    assert forest[0].name == "bush_1" and forest[0].hand_placed and forest[0].id == 1
    assert forest[0].species == "bush"
    assert forest[-1].name == forest.trees[-1].name

    forest.export(tmp_path / "py" / "forest.obj")
    stats = sylva.load_project(project).export_forest(tmp_path / "stream" / "forest.obj")
    assert stats["vertices"] == cli_stats["vertices"]
    cli_bytes = (tmp_path / "cli" / "forest.obj").read_bytes()
    assert (tmp_path / "py" / "forest.obj").read_bytes() == cli_bytes
    assert (tmp_path / "stream" / "forest.obj").read_bytes() == cli_bytes
    assert (tmp_path / "py" / "forest.mtl").read_bytes() == \
        (tmp_path / "cli" / "forest.mtl").read_bytes()


def without_fbx_timestamp(data):
    """Assimp writes the wall-clock time into an FBX header (CreationTimeStamp: Year ...
    Millisecond), so two exports a second apart differ there and only there."""
    start = data.index(b"CreationTimeStamp")
    end = data.index(b"Millisecond", start) + len(b"Millisecond") + 5  # 'I' + int32
    return data[:start] + bytes(end - start) + data[end:]


def test_forest_glb_and_fbx_equal_cli(data, cli, tmp_path):
    project = data / "projects" / "small.sylva"
    forest = sylva.load_project(project).build_forest()
    for ext in ("glb", "fbx"):
        cli("forest", project, "-o", tmp_path / f"cli.{ext}")
        forest.export(tmp_path / f"py.{ext}")
        py, ref = (tmp_path / f"py.{ext}").read_bytes(), (tmp_path / f"cli.{ext}").read_bytes()
        if ext == "fbx":
            py, ref = without_fbx_timestamp(py), without_fbx_timestamp(ref)
        assert py == ref, ext


def test_transform_places_the_mesh(data):
    forest = sylva.load_project(data / "projects" / "small.sylva").build_forest()
    tree = forest[5]
    local = tree.mesh.positions
    m = tree.transform
    world = (np.c_[local, np.ones(len(local))] @ m.T)[:, :3]
    assert np.allclose(world, tree.world_positions(), atol=1e-4)
    assert np.allclose(m[:3, 3], tree.position)
    assert tree.metrics["height_m"] > 0


def test_obstacles_as_arrays_equal_obstacle_files(data, tmp_path):
    project = data / "projects" / "small.sylva"
    from_file = sylva.load_project(project)
    from_file.export_forest(tmp_path / "file.obj")

    from_arrays = sylva.load_project(project)
    from_arrays.clear_obstacles()
    vertices, triangles = read_obj_mesh(data / "obstacles" / "wall.obj")
    from_arrays.add_obstacle(vertices=vertices, triangles=triangles, name="wall")
    stats = from_arrays.export_forest(tmp_path / "arrays.obj")
    assert stats["obstacle_triangles"] == 12 and stats["colliding_trees"] > 0
    a = (tmp_path / "file.obj").read_bytes().replace(b"mtllib file.mtl", b"")
    b = (tmp_path / "arrays.obj").read_bytes().replace(b"mtllib arrays.mtl", b"")
    assert a == b

    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        from_arrays.add_obstacle(vertices=np.zeros((4, 2)), triangles=[[0, 1, 2]])
    with pytest.raises(ValueError, match="out of range|index"):
        from_arrays.add_obstacle(vertices=np.zeros((3, 3)), triangles=[[0, 1, 7]])


def test_project_in_memory_with_a_ground(data, presets):
    p = sylva.Project(seed=4)
    p.add_species("bush", data / "lsystem" / "bush.lsys")
    alder = sylva.load_species(presets / "alder.json")
    alder.set_param("grow.generations", 4)
    p.add_species("alder", alder)  # inline, its grammar file rebased
    # a 20 m square ground raised to y = 2
    ground = np.array([[-10, 2, -10], [10, 2, -10], [10, 2, 10], [-10, 2, 10]], float)
    p.set_ground(ground, [[0, 2, 1], [0, 3, 2]], counts={"bush": 6, "alder": 3})
    p.add_tree("alder", (0, 2, 0), rotation=45, seed=9)
    forest = p.build_forest()
    assert len(forest) == 10
    assert forest[0].species == "alder" and forest[0].hand_placed
    for t in forest.trees:
        assert -10 <= t.position[0] <= 10 and -10 <= t.position[2] <= 10
        assert t.position[1] == pytest.approx(2.0, abs=1e-4)
    assert forest.stats["metrics"]["co2_kg"] > 0
    with pytest.raises(ValueError, match="no species 'oak'"):
        p.add_domain({"oak": 3})
    with pytest.raises(ValueError, match="cannot be saved"):
        p.save("/tmp/never-written.sylva")


def test_project_parts_read_as_the_editor_reads_them(data, tmp_path):
    # sylva.Tree, the obstacle and domain dicts: the types the editor's document gives too.
    p = sylva.Project(seed=4)
    p.add_species("bush", data / "lsystem" / "bush.lsys")
    p.add_domain({"bush": 3}, min=(-5, -6), max=(5, 6))
    first = p.add_tree("bush", (1, 0, 2), rotation=30, scale=1.5, growth=0.5, seed=9)
    second = p.add_tree("bush", (3, 0, 4))
    assert (first, second) == (1, 2)  # stable ids, as the editor's document gives them
    trees = p.trees()
    assert all(isinstance(t, sylva.Tree) for t in trees)
    t = p.tree(1)
    assert (t.id, t.species, t.position, t.rotation, t.scale, t.growth, t.seed) == (
        1, "bush", (1.0, 0.0, 2.0), 30.0, 1.5, 0.5, 9)
    # Derived from the project seed and the trees before it, as the editor does
    # (doc::Project::newTreeSeed: mixSeed(4, 2) % 1000000007).
    assert trees[1].seed == 317578722
    with pytest.raises(ValueError, match="there is no tree 3"):
        p.tree(3)
    assert p.domains == [{"id": 1, "shape": "rectangle", "min": (-5.0, -6.0), "max": (5.0, 6.0),
                          "counts": {"bush": 3}}]
    with pytest.raises(ValueError, match=r"min needs two numbers \(x, z\)"):
        p.add_domain({"bush": 1}, min=(0, 0, 0))
    p.add_obstacle(file=tmp_path / "wall.obj", translate=(0, 0, 3), scale=(2, 1, 1))
    p.add_obstacle(vertices=[[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles=[[0, 1, 2]])
    assert p.obstacle_count == 2
    assert p.obstacles == [{"file": str(tmp_path / "wall.obj"), "translate": (0.0, 0.0, 3.0),
                            "rotate": (0.0, 0.0, 0.0), "scale": (2.0, 1.0, 1.0)}]


def test_variants_instances_and_ids(data, tmp_path):
    # Issue 30: free domain trees are instances of their species' K variants; every tree has a
    # stable id; moving one tree keeps every other tree's id and transform.
    project = sylva.load_project(data / "projects" / "small.sylva")
    assert project.variants == {"bush": 8, "shrub": 8}
    project.set_variants("bush", 3)
    forest = project.build_forest(lod=False)
    s = forest.stats
    assert s["instanced"] + s["unique"] == s["trees"] == len(forest)
    assert s["instanced"] > 0 and s["variants"] == 3 + 8
    variants = forest.variants
    assert [v.name for v in variants[:4]] == ["bush_v0", "bush_v1", "bush_v2", "shrub_v0"]
    assert all(v.index == i for i, v in enumerate(variants))
    assert variants[3].species == "shrub" and variants[3].species_variant == 0
    instanced = [t for t in forest.trees if t.instanced]
    assert len(instanced) == s["instanced"]
    for t in forest.trees:
        assert (t.variant is None) == (not t.instanced)
        assert t.name.endswith("_%d" % t.id)
        # a unique domain tree is adapted from its variant's skeleton; hand-placed ones grow
        if t.instanced or t.hand_placed:
            assert t.adapted_from is None
        else:
            assert variants[t.adapted_from].species == t.species
    assert any(t.adapted_from is not None for t in forest.trees)
    for t in instanced:
        v = variants[t.variant]
        assert v.species == t.species
        # without the camera LOD the tree shows its variant's very mesh
        assert np.array_equal(t.mesh.positions, v.mesh.positions)
    assert not forest[0].instanced  # hand-placed trees are always grown from their seed
    assert len({t.id for t in forest.trees}) == len(forest)
    assert forest.tree_by_id(forest[7].id).name == forest[7].name
    with pytest.raises(KeyError):
        forest.tree_by_id(12345)
    with pytest.raises(ValueError, match=r"variants of 'bush'.*\[0, 256\]"):
        project.set_variants("bush", 257)

    # Move the hand-placed tree 30 m: every other tree keeps its id and transform, except the
    # few it stood on or stands on now.
    before = {t.id: t.transform for t in forest.trees}
    tree = project.trees()[0]
    project.save(tmp_path / "p.sylva")
    text = json.loads((tmp_path / "p.sylva").read_text())
    assert text["format_version"] == 2 and text["instances"][0]["id"] == tree.id
    text["instances"][0]["position"][0] += 30
    (tmp_path / "p.sylva").write_text(json.dumps(text))
    moved = sylva.load_project(tmp_path / "p.sylva")
    moved.set_variants("bush", 3)
    after = {t.id: t.transform for t in moved.build_forest(lod=False).trees}
    changed = [i for i in before if i not in after or not np.array_equal(before[i], after[i])]
    assert tree.id in changed
    assert len(changed) <= 3, changed
    assert len(set(before) & set(after)) >= len(before) - 2

    unique = project.build_forest(lod=False, instancing=False)
    assert unique.stats["instanced"] == 0 and unique.variants == []


def big_project(data, trees=600):
    p = sylva.Project(seed=1)
    p.add_species("bush", data / "lsystem" / "bush.lsys")
    p.add_domain({"bush": trees}, min=(-60, -60), max=(60, 60))
    return p


def test_gil_released_and_progress_reported(data):
    p = big_project(data)
    ticks = []
    stop = threading.Event()

    def other_thread():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    reports = []
    caller = threading.get_ident()

    def progress(fraction, stage):
        assert threading.get_ident() == caller
        reports.append((time.perf_counter(), fraction, stage))

    worker = threading.Thread(target=other_thread)
    worker.start()
    t0 = time.perf_counter()
    # Every tree grown (no instancing): 600 instanced bushes take their variants' levels and
    # the build lasted 4 ms, too short for the other thread to show whether the GIL was held.
    forest = p.build_forest(progress=progress, instancing=False)
    t1 = time.perf_counter()
    stop.set()
    worker.join()
    assert len(forest) == 600
    fractions = [f for _, f, s in reports if s == "trees"]
    assert len(fractions) >= 5 and fractions == sorted(fractions) and fractions[-1] == 1.0
    during = [t for t in ticks if t0 < t < t1]
    print(f"build {1000 * (t1 - t0):.0f} ms, {len(reports)} progress calls, "
          f"{len(during)} ticks of a parallel Python thread during the build")
    # With the GIL held for the whole build the other thread could not run at all.
    assert len(during) >= 5


def test_callback_exception_stops_and_writes_nothing(data, tmp_path):
    p = big_project(data)

    class Stop(Exception):
        pass

    def progress(fraction, stage):
        if fraction > 0.2:
            raise Stop()

    with pytest.raises(Stop):
        p.export_forest(tmp_path / "forest.obj", progress=progress)
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_raises_keyboard_interrupt_and_writes_nothing(data, tmp_path):
    script = f"""
import sys, sylva
p = sylva.Project(seed=1)
p.add_species("bush", {str(data / "lsystem" / "bush.lsys")!r})
p.add_domain({{"bush": 20000}}, min=(-300, -300), max=(300, 300))
def progress(fraction, stage):
    print("progress", fraction, flush=True)
try:
    p.export_forest({str(tmp_path / "forest.obj")!r}, progress=progress, threads=1)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(42)
print("finished", flush=True)
"""
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                            env=os.environ.copy())
    first = proc.stdout.readline()
    assert first.startswith("progress"), first
    t = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=60)
    latency = time.perf_counter() - t
    print(f"Ctrl-C to KeyboardInterrupt: {1000 * latency:.0f} ms")
    assert proc.returncode == 42, out
    assert "interrupted" in out
    assert list(tmp_path.iterdir()) == []


def test_bad_project_errors_match_cli(data, cli, tmp_path):
    bad = tmp_path / "bad.sylva"
    bad.write_text('{"format": "sylva-project", "format_version": 1, "species": [ }')
    r = cli("forest", bad, "-o", tmp_path / "x.obj", check=False)
    assert r.returncode == 1
    with pytest.raises(ValueError) as e:
        sylva.load_project(bad)
    assert str(e.value) == r.stderr.strip().removeprefix("sylva-cli: error: ")
    with pytest.raises(OSError):
        sylva.load_project(tmp_path / "missing.sylva")
    p = sylva.Project()
    p.add_species("bush", data / "lsystem" / "bush.lsys")
    p.add_obstacle(file=tmp_path / "missing.obj")
    with pytest.raises(OSError, match="missing.obj"):
        p.build_forest()


def test_every_front_door_writes_the_same_bytes_with_a_wind_and_a_tile(data, cli, tmp_path):
    """Issue #42: one export use case (document/projectexport) behind `sylva-cli forest` and
    `Project.export_forest`. A project with a wind: the project's wind is the default of both
    (the CLI ignored it before); tile 2/4 of OBJ, GLB with its wind, and USD (Python's USD tiles
    were marked as the whole forest, so `compose` refused them); the same statistics keys."""
    project = json.loads((data / "projects" / "small.sylva").read_text())
    base = data / "projects"
    for s in project["species"]:
        s["file"] = str((base / s["file"]).resolve())
    for o in project["obstacles"]:
        o["file"] = str((base / o["file"]).resolve())
    project["wind"] = {"direction": [0.6, 0, 0.8], "strength": 1.3, "gustiness": 0.7,
                       "frequency": 0.9}
    windy = tmp_path / "windy.sylva"
    windy.write_text(json.dumps(project))
    calm = dict(project)
    del calm["wind"]
    (tmp_path / "calm.sylva").write_text(json.dumps(calm))
    for d in ("cli", "py", "calm", "tiles"):
        (tmp_path / d).mkdir()

    p = sylva.load_project(windy)
    for name in ("forest.obj", "forest.glb", "forest.usda"):
        r = cli("forest", windy, "-o", tmp_path / "cli" / name, "--tile", "2/4", "--stats")
        cli_stats = json.loads(r.stdout)
        py_stats = p.export_forest(tmp_path / "py" / name, tile=(2, 4))
        assert sorted(py_stats) == sorted(cli_stats), name
        for key in ("trees", "trees_in_scene", "tile", "tiles", "vertices", "triangles",
                    "instanced", "unique", "variants"):
            assert py_stats[key] == cli_stats[key], (name, key)
        assert cli_stats["tile"] == 2 and cli_stats["tiles"] == 4
        a = (tmp_path / "cli" / name).read_bytes()
        b = (tmp_path / "py" / name).read_bytes()
        if name.endswith(".obj"):
            a = a.replace(b"mtllib forest.mtl", b"")
            b = b.replace(b"mtllib forest.mtl", b"")
        assert a == b, name
    # The wind came from the project: the calm project's GLB has none, the windy one's a clip,
    # and the project's settings shape it (a flag overrides one of them).
    cli("forest", tmp_path / "calm.sylva", "-o", tmp_path / "calm" / "forest.glb", "--tile", "2/4")
    assert (tmp_path / "calm" / "forest.glb").read_bytes() != (tmp_path / "cli" / "forest.glb").read_bytes()
    assert b'"wind"' in (tmp_path / "cli" / "forest.glb").read_bytes()
    assert (tmp_path / "cli" / "forest.wind.csv").exists()
    cli("forest", windy, "-o", tmp_path / "calm" / "strong.glb", "--tile", "2/4",
        "--wind-strength", "0.2")
    p.export_forest(tmp_path / "py" / "strong.glb", tile="2/4", strength=0.2)
    assert (tmp_path / "calm" / "strong.glb").read_bytes() == (tmp_path / "py" / "strong.glb").read_bytes()
    assert (tmp_path / "calm" / "strong.glb").read_bytes() != (tmp_path / "cli" / "forest.glb").read_bytes()
    cli("forest", windy, "-o", tmp_path / "calm" / "nowind.glb", "--tile", "2/4", "--no-wind")
    p.export_forest(tmp_path / "py" / "nowind.glb", tile="2/4", wind=False)
    assert (tmp_path / "calm" / "nowind.glb").read_bytes() == (tmp_path / "py" / "nowind.glb").read_bytes()

    # Python's USD tiles compose into the forest the CLI's single run writes.
    for i in range(1, 5):
        p.export_forest(tmp_path / "tiles" / ("forest_%d.usda" % i), tile=(i, 4))
    cli("compose", tmp_path / "tiles" / "forest.usda",
        *[tmp_path / "tiles" / ("forest_%d.usda" % i) for i in range(1, 5)])
    assert (tmp_path / "tiles" / "forest.usda").exists()


def test_branch_edits_of_a_hand_placed_tree(data, presets, tmp_path):
    # Issue #43: Project.edit_branch keeps hand edits of single branches by their stable ids;
    # the forest applies them (pruning a limb lowers the triangles and the wood), and an edit of
    # a branch the tree lacks is reported, not an error; the project saves as format 3.
    p = sylva.Project(seed=4)
    p.add_species("alder", sylva.load_species(presets / "alder.json"))
    tid = p.add_tree("alder", (0, 0, 0), seed=11)
    plain = p.build_forest(lod=False)
    p.edit_branch(tid, "0.1", prune=True)
    assert p.branch_edits(tid) == [{"branch": "0.1", "prune": True}]
    pruned = p.build_forest(lod=False)
    assert pruned.stats["triangles"] < plain.stats["triangles"]
    assert pruned.stats["metrics"]["wood_volume_m3"] < plain.stats["metrics"]["wood_volume_m3"]
    assert pruned.stats["branch_edits"] == 1 and pruned.stats["warnings"] == []
    p.edit_branch(tid, "0.1", prune=False)
    assert p.branch_edits(tid) == []
    p.edit_branch(tid, "0.999.3", length=0.5)
    orphan = p.build_forest(lod=False)
    assert orphan.stats["orphaned_edits"] == 1
    assert "branch 0.999.3" in orphan.stats["warnings"][0]
    with pytest.raises(ValueError, match=r"length 30 is out of range \[0.05, 20\]"):
        p.edit_branch(tid, "0.1", length=30)
    with pytest.raises(ValueError, match="non-zero"):
        p.edit_branch(tid, "0.1", bend=(0, 0, 0))
    p.save(tmp_path / "edited.sylva")
    text = (tmp_path / "edited.sylva").read_text()
    assert '"format_version": 3' in text and '"branch_edits"' in text
    assert sylva.load_project(tmp_path / "edited.sylva").branch_edits(tid) == p.branch_edits(tid)

    # lock=True keeps the branch's geometry (the tree is grown to copy it), not only a flag: the
    # locked nodes are stored, and the forest applies the locked edit.
    p.edit_branch(tid, "0.999.3", length=1.0)
    p.edit_branch(tid, "0.1", bend=(1, 1, 0), lock=True)
    locked = p.branch_edits(tid)[0]
    assert locked["lock"] and locked["locked_nodes"] > 1, locked
    with pytest.raises(ValueError, match="is locked"):
        p.edit_branch(tid, "0.1", length=0.5)
    regrown = p.build_forest(lod=False)
    assert regrown.stats["branch_edits"] == 1 and regrown.stats["orphaned_edits"] == 0
    with pytest.raises(ValueError, match="no branch 0.77"):
        p.edit_branch(tid, "0.77", lock=True)


def glb_json(path):
    import struct

    data = path.read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    chunk_length, chunk_type = struct.unpack_from("<II", data, 12)
    assert chunk_type == 0x4E4F534A  # JSON
    return json.loads(data[20:20 + chunk_length])


def test_edited_tree_exports_the_same_through_every_door(presets, cli, tmp_path):
    # Issue #43: a project with hand edits of single branches exports the same bytes from
    # sylva-cli and Python (OBJ, and glTF with the wind rig), and the rig is built from the
    # edited tree: pruning a limb lowers the rigged triangles, the wood and the CO2.
    p = sylva.Project(seed=4)
    p.add_species("alder", sylva.load_species(presets / "alder.json"))
    tid = p.add_tree("alder", (0, 0, 0), seed=11)
    p.save(tmp_path / "plain.sylva")
    p.edit_branch(tid, "0.1", prune=True)
    p.edit_branch(tid, "0.2", bend=(1, 1, 0), length=0.8, radius=1.3)
    p.save(tmp_path / "edited.sylva")
    for name, wind in (("forest.obj", False), ("forest.glb", True)):
        extra = ["--wind", "--bones", 16, "--clip-length", 2] if wind else []
        (tmp_path / "cli").mkdir(exist_ok=True)
        cli("forest", tmp_path / "edited.sylva", "-o", tmp_path / "cli" / name, *extra)
        kwargs = dict(wind=True, bones=16, clip_length=2.0) if wind else {}
        (tmp_path / "py").mkdir(exist_ok=True)
        sylva.load_project(tmp_path / "edited.sylva").export_forest(tmp_path / "py" / name, **kwargs)
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "py" / name).read_bytes(), name
    edited = sylva.load_project(tmp_path / "edited.sylva").build_forest(wind=True, lod=False)
    plain = sylva.load_project(tmp_path / "plain.sylva").build_forest(wind=True, lod=False)
    assert edited.stats["branch_edits"] == 2 and edited.stats["orphaned_edits"] == 0
    assert edited.stats["triangles"] < plain.stats["triangles"]
    assert edited.stats["metrics"]["co2_kg"] < plain.stats["metrics"]["co2_kg"]
    edited.export(tmp_path / "edited.glb", wind=True, bones=16, clip_length=2.0)
    plain.export(tmp_path / "plain.glb", wind=True, bones=16, clip_length=2.0)
    rigged = [glb_json(tmp_path / n) for n in ("edited.glb", "plain.glb")]
    counts = [sum(d["accessors"][pr["attributes"]["POSITION"]]["count"]
                  for m in d["meshes"] for pr in m["primitives"]) for d in rigged]
    assert all(len(d["skins"]) == 1 for d in rigged)
    assert counts[0] < counts[1], counts
