"""sylva species: load (file, dict), parameters, grow → skeleton and mesh arrays, export,
errors as the CLI reports them."""
import json

import numpy as np
import pytest

import sylva


def test_module_basics(presets):
    assert sylva.__version__
    assert sylva.presets_dir() == str(presets)
    assert "lsystem" in sylva.node_types()
    assert "generations" in sylva.node_types()["lsystem"]


def test_grow_gives_numpy_skeleton_and_mesh(presets):
    species = sylva.load_species(presets / "ternary-tree.json")
    assert species.name == "Ternary tree (ABOP 2.8)"
    assert species.node_ids == ["grow", "mesh"]
    tree = species.grow(seed=7)
    sk = tree.skeleton
    n = len(sk)
    assert n > 100
    assert sk.positions.shape == (n, 3) and sk.positions.dtype == np.float32
    assert sk.parents.shape == (n,) and sk.parents.dtype == np.int32
    assert sk.radii.shape == (n,) and sk.orders.shape == (n,)
    assert sk.parents[0] == -1
    assert np.all(sk.parents[1:] < np.arange(1, n))  # parents before children
    assert np.all(sk.radii > 0)
    mesh = tree.mesh
    v = mesh.vertex_count
    assert mesh.positions.shape == (v, 3)
    assert mesh.normals.shape == (v, 3)
    assert mesh.uvs.shape == (v, 2)
    assert mesh.indices.shape == (mesh.triangle_count, 3)
    assert mesh.indices.max() < v
    # indices per material cover every triangle exactly once
    total = sum(len(mesh.indices_of(m)) for m in mesh.materials)
    assert total == mesh.triangle_count
    m = tree.metrics()
    assert m["height_m"] > 1 and m["co2_kg"] > 0


def test_leaves_are_their_own_material(presets):
    tree = sylva.load_species(presets / "alder.json").grow(seed=3)
    assert set(tree.mesh.materials) == {"bark", "leaf"}
    leaf = tree.mesh.indices_of("leaf")
    assert leaf.shape[1] == 3 and len(leaf) > 0


def test_leaf_tints_are_per_vertex_colours(presets):
    # A library species sets leaf_hue_variation and the others: each leaf card one linear RGBA multiplier,
    # white on bark; a species without it has no colours.
    tree = sylva.load_species(presets / "english-oak.json").grow(seed=1)
    mesh = tree.mesh
    assert mesh.colors.shape == (mesh.vertex_count, 4) and mesh.colors.dtype == np.uint8
    bark = np.unique(mesh.indices_of("bark"))
    assert np.all(mesh.colors[bark] == 255)
    leaf = np.unique(mesh.indices_of("leaf"))
    assert len(np.unique(mesh.colors[leaf], axis=0)) > 100
    assert sylva.load_species(presets / "alder.json").grow(seed=3).mesh.colors.shape == (0, 4)


def test_same_seed_same_tree_other_seed_other_tree(presets):
    s = sylva.load_species(presets / "alder.json")
    a = s.grow(seed=5).mesh.positions
    b = sylva.load_species(presets / "alder.json").grow(seed=5).mesh.positions
    c = s.grow(seed=6).mesh.positions
    assert np.array_equal(a, b)
    assert a.shape != c.shape or not np.array_equal(a, c)


def test_species_from_dict_equals_file(presets):
    path = presets / "ternary-tree.json"
    d = json.loads(path.read_text())
    from_dict = sylva.load_species(d, base_dir=presets)
    from_file = sylva.load_species(path)
    assert from_dict.to_dict()["graph"] == from_file.to_dict()["graph"]
    assert np.array_equal(from_dict.grow(seed=1).mesh.positions,
                          from_file.grow(seed=1).mesh.positions)


def test_parameters_read_set_and_validated(presets):
    s = sylva.load_species(presets / "ternary-tree.json")
    assert s.get_param("mesh.resolution") == 8
    assert s.get_param("grow.generations") is None
    before = s.grow(seed=1).mesh.vertex_count
    s.set_param("mesh.resolution", 4)
    assert s.get_param("mesh.resolution") == 4
    assert s.grow(seed=1).mesh.vertex_count < before
    with pytest.raises(ValueError, match="has no parameter 'bogus'"):
        s.set_param("grow.bogus", 1)
    with pytest.raises(ValueError, match="no node 'nope'"):
        s.set_param("nope.x", 1)
    with pytest.raises(ValueError, match="node.param"):
        s.set_param("resolution", 1)
    # out of range: refused when set, with the range from the node metadata; nothing changes
    with pytest.raises(ValueError, match=r"resolution must be in \[3, 64\], got -3"):
        s.set_param("mesh.resolution", -3)
    assert s.get_param("mesh.resolution") == 4


def test_tree_export_equals_cli_bytes(presets, cli, tmp_path):
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    s = sylva.load_species(presets / "alder.json")
    s.set_param("grow.generations", 5)
    written = s.grow(seed=7).export(tmp_path / "py" / "tree.obj")
    assert written[0].endswith("tree.obj")
    cli("tree", presets / "alder.json", "--seed", 7, "--set", "grow.generations=5",
        "-o", tmp_path / "cli" / "tree.obj")
    for name in ("tree.obj", "tree.mtl"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert (tmp_path / "py" / "textures").is_dir()
    sylva.grow(presets / "ternary-tree.json", seed=2).export(tmp_path / "py" / "t.glb")
    cli("tree", presets / "ternary-tree.json", "--seed", 2, "-o", tmp_path / "cli" / "t.glb")
    assert (tmp_path / "py" / "t.glb").read_bytes() == (tmp_path / "cli" / "t.glb").read_bytes()


def test_write_lods_equals_cli_bytes(data, cli, tmp_path):
    # Issue #32: the game LOD chain from Python is `sylva-cli lods`'s, file for file.
    s = sylva.load_species(data / "lsystem" / "bush.lsys")
    d = s.write_lods(tmp_path / "py", budgets=[1, 0.35, 0.12], impostor_grid=4,
                     impostor_cell=32)
    assert [level["name"] for level in d["levels"]] == ["bush_LOD0", "bush_LOD1", "bush_LOD2"]
    assert d["levels"][0]["triangles"] > d["levels"][1]["triangles"]
    assert d["impostor"]["grid"] == 4 and d["impostor"]["atlas_pixels"] == 128
    cli("lods", data / "lsystem" / "bush.lsys", "-o", tmp_path / "cli", "--budgets",
        "1,0.35,0.12", "--impostor-grid", 4, "--impostor-cell", 32)
    for name in ("bush_LODs.glb", "bush_lods.json", "bush_impostor_color.png",
                 "bush_impostor_normal.png", "bush_impostor_depth.png", "bush_LOD2.obj"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    with pytest.raises(ValueError, match="LOD2 budget must be above 0"):
        s.write_lods(tmp_path / "bad", budgets=[1, 0.3, 0.5])


def cli_message(r):
    """The CLI's message without its 'sylva-cli: error: ' prefix."""
    return r.stderr.strip().removeprefix("sylva-cli: error: ")


def test_errors_say_what_the_cli_says(data, cli, tmp_path):
    bad = tmp_path / "bad.lsys"
    bad.write_text("axiom: F\nF -> F[+F\n")
    r = cli("tree", bad, "-o", tmp_path / "x.obj", check=False)
    assert r.returncode == 1
    with pytest.raises(ValueError) as e:
        sylva.load_species(bad).grow()
    assert str(e.value) == cli_message(r)

    missing = tmp_path / "missing.json"
    r = cli("tree", missing, "-o", tmp_path / "x.obj", check=False)
    with pytest.raises(OSError) as e:
        sylva.load_species(missing)
    assert str(e.value) == cli_message(r)

    r = cli("tree", data / "lsystem" / "bush.lsys", "--set", "grow.nope=1", "-o",
            tmp_path / "x.obj", check=False)
    s = sylva.load_species(data / "lsystem" / "bush.lsys")
    with pytest.raises(ValueError) as e:
        s.set_param("grow.nope", 1)
    assert str(e.value) == cli_message(r)

    with pytest.raises(ValueError, match="parameter value"):
        s.set_param("grow.generations", object())
    assert not (tmp_path / "x.obj").exists()


def test_grow_reports_progress_and_stops_when_the_callback_raises(presets):
    s = sylva.load_species(presets / "so-broadleaf.json")
    reports = []
    s.grow(seed=1, progress=lambda f, stage: reports.append((f, stage)))
    stages = [stage for _, stage in reports]
    assert "grow" in stages and "mesh" in stages and len(reports) >= 5

    class Stop(Exception):
        pass

    def stop(fraction, stage):
        if stage == "grow" and fraction > 0.1:
            raise Stop()

    with pytest.raises(Stop):
        s.grow(seed=2, progress=stop)
    # The species is still usable and grows the same tree as before.
    again = s.grow(seed=2).mesh.positions
    assert np.array_equal(again, sylva.load_species(presets / "so-broadleaf.json")
                          .grow(seed=2).mesh.positions)
    with pytest.raises(ValueError, match="callable"):
        s.grow(seed=2, progress=42)


def test_seasons_change_the_leaves_and_leave_the_species_as_it_was(presets):
    oak = sylva.load_species(presets / "english-oak.json")
    summer = oak.grow(seed=2)
    assert "leaf" in summer.mesh.materials
    winter = oak.grow(seed=2, season="winter")
    assert len(winter.mesh.indices_of("leaf")) == 0  # a bare broadleaf
    assert len(winter.mesh.indices_of("bark")) == len(summer.mesh.indices_of("bark"))
    autumn = oak.grow(seed=2, season="autumn")
    assert 0 < len(autumn.mesh.indices_of("leaf")) < len(summer.mesh.indices_of("leaf"))
    # The season was for that growth only: the species grows in summer again.
    assert oak.get_param("mesh.season") is None
    again = oak.grow(seed=2)
    assert len(again.mesh.indices_of("leaf")) == len(summer.mesh.indices_of("leaf"))
    # A conifer is the same in every season.
    pine = sylva.load_species(presets / "scots-pine.json")
    assert np.array_equal(pine.grow(seed=2).mesh.positions,
                          pine.grow(seed=2, season="winter").mesh.positions)
    with pytest.raises(ValueError, match="spring, summer, autumn or winter"):
        oak.grow(seed=2, season="monsoon")
    assert sylva.grow(presets / "english-oak.json", seed=2, season="winter").mesh.indices_of(
        "leaf").shape[0] == 0


def test_project_and_tree_seasons(presets, tmp_path):
    p = sylva.Project(seed=1)
    p.add_species("oak", presets / "english-oak.json")
    assert p.season is None
    p.add_tree("oak", (0, 0, 0), seed=1)
    spring = p.add_tree("oak", (30, 0, 0), seed=2, season="spring")
    p.season = "winter"
    assert p.season == "winter" and p.trees()[1].season == "spring" and p.trees()[0].season is None
    forest = p.build_forest(lod=False)
    assert len(forest[0].mesh.indices_of("leaf")) == 0  # the project's winter
    assert len(forest[1].mesh.indices_of("leaf")) > 0  # its own spring
    p.set_tree_season(spring, None)  # by the tree's id
    assert p.trees()[1].season is None and p.tree(spring).season is None
    with pytest.raises(ValueError):
        p.set_tree_season(99, "winter")
    with pytest.raises(ValueError):
        p.season = "monsoon"
    p.season = "autumn"
    p.save(tmp_path / "seasons.sylva")
    assert sylva.load_project(tmp_path / "seasons.sylva").season == "autumn"


_MMAPPED_BLOCKS = r"""
import ctypes, sys
class MallInfo2(ctypes.Structure):
    _fields_ = [(n, ctypes.c_size_t) for n in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks",
                 "uordblks", "fordblks", "keepcost")]
libc = ctypes.CDLL(None)
libc.mallinfo2.restype = MallInfo2
import sylva
before = libc.mallinfo2().hblks
block = bytearray(8 << 20)  # 8 MiB: past glibc's default mmap threshold
print(libc.mallinfo2().hblks - before)
"""


def test_import_keeps_freed_tree_arrays_unless_told_not_to(tmp_path):
    """At import the module raises glibc's mmap threshold (docs/python.md, memory): an 8 MiB
    array then comes from the heap, not from a fresh mapping; SYLVA_MALLOC=system leaves the
    host's policy, under which it is mapped."""
    import os
    import subprocess
    import sys

    def mapped(env_extra):
        env = dict(os.environ, **env_extra)
        out = subprocess.run([sys.executable, "-c", _MMAPPED_BLOCKS], env=env, check=True,
                             capture_output=True, text=True).stdout
        return int(out.strip())

    assert mapped({}) == 0
    assert mapped({"SYLVA_MALLOC": "system"}) == 1
