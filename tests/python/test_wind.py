"""sylva wind (#31): tree.export(path, wind=True) writes a GLB with a skin and a looping
animation (read from the GLB's own JSON chunk), the same bytes as `sylva-cli tree --wind`,
settings checked with their ranges; the project's wind is readable and settable."""
import json
import pathlib
import re
import struct

import pytest

import sylva


def glb_json(path):
    data = path.read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    chunk_length, chunk_type = struct.unpack_from("<II", data, 12)
    assert chunk_type == 0x4E4F534A  # JSON
    return json.loads(data[20:20 + chunk_length])


def test_wind_glb_has_skin_and_animation(presets, tmp_path, cli):
    species = sylva.load_species(presets / "ternary-tree.json")
    tree = species.grow(seed=3)  # grown without wind data: export grows it again with it
    out = tmp_path / "wind.glb"
    written = tree.export(out, wind=True, bones=12, clip_length=2.0, strength=1.0)
    assert written[0] == str(out)
    doc = glb_json(out)
    assert len(doc["skins"]) == 1
    joints = doc["skins"][0]["joints"]
    assert 2 <= len(joints) <= 12
    (anim,) = doc["animations"]
    assert anim["name"] == "wind" and anim["channels"]
    times = doc["accessors"][anim["samplers"][0]["input"]]
    assert times["min"][0] == pytest.approx(0.0) and times["max"][0] == pytest.approx(2.0)
    prim = doc["meshes"][0]["primitives"][0]
    assert "JOINTS_0" in prim["attributes"] and "WEIGHTS_0" in prim["attributes"]
    assert any(a.startswith("_WIND") for a in prim["attributes"])
    # The same tree grown with wind data, and sylva-cli, write the same bytes.
    again = tmp_path / "again.glb"
    species.grow(seed=3, wind=True).export(again, wind=True, bones=12, clip_length=2.0,
                                           strength=1.0)
    assert again.read_bytes() == out.read_bytes()
    by_cli = tmp_path / "cli.glb"
    cli("tree", presets / "ternary-tree.json", "--seed", 3, "-o", by_cli, "--wind",
        "--bones", 12, "--clip-length", 2, "--wind-strength", 1)
    assert by_cli.read_bytes() == out.read_bytes()
    # Without wind: no skin, no animation.
    still = tmp_path / "still.glb"
    tree.export(still)
    assert "skins" not in glb_json(still) and "animations" not in glb_json(still)


def test_wind_settings_are_checked(presets, tmp_path):
    tree = sylva.load_species(presets / "ternary-tree.json").grow(seed=3)
    with pytest.raises(ValueError, match="strength"):
        tree.export(tmp_path / "x.glb", wind=True, strength=5)
    with pytest.raises(ValueError, match="wind=True"):
        tree.export(tmp_path / "x.glb", strength=1)
    assert not (tmp_path / "x.glb").exists()


def test_cli_wind_flags_take_the_settings_range(presets, tmp_path, cli):
    """The CLI's wind options are checked against the project settings' spec, the range the
    editor's Properties and Python's project wind accept, and each is named with its option."""
    out = tmp_path / "x.glb"
    demo = presets.parent / "resources" / "demo" / "forest.sylva"
    cases = [("--wind-strength", 3, r"--wind-strength: wind.strength must be in \[0, 2\], got 3"),
             ("--wind-gustiness", 1.5, r"--wind-gustiness: wind.gustiness must be in \[0, 1\]"),
             ("--wind-frequency", 0, r"--wind-frequency: wind.frequency must be in \[0.05, 5\]")]
    for flag, bad, text in cases:
        for command in (["tree", presets / "ternary-tree.json"], ["forest", demo]):
            r = cli(*command, "-o", out, "--wind", flag, bad, check=False)
            assert r.returncode == 1, r.stderr
            assert re.search(text, r.stderr), r.stderr
            assert not out.exists()
    # Both ends of each range are accepted.
    cli("tree", presets / "ternary-tree.json", "-o", out, "--wind", "--wind-strength", 2,
        "--wind-gustiness", 0, "--wind-frequency", 5)
    assert out.exists()


def test_project_wind(tmp_path):
    project = sylva.Project(seed=1, base_dir=tmp_path)
    assert project.wind is None
    project.wind = {"direction": (0, 0, 1), "strength": 1.5}
    w = project.wind
    assert w["direction"] == (0.0, 0.0, 1.0) and w["strength"] == 1.5
    assert w["gustiness"] == pytest.approx(0.3)  # not given: the default
    with pytest.raises(ValueError, match="gustiness"):
        project.wind = {"gustiness": 2}
    with pytest.raises(ValueError, match="unknown wind setting"):
        project.wind = {"speed": 1}
    assert project.wind["strength"] == 1.5
    path = tmp_path / "p.sylva"
    project.save(path)
    assert json.loads(path.read_text())["wind"]["strength"] == 1.5
    project.wind = None
    project.save(path)
    assert "wind" not in json.loads(path.read_text())


def test_forest_wind_export_equals_cli(data, cli, tmp_path):
    """Forest.export(path, wind=True) writes what `sylva-cli forest --wind` writes, byte for byte
    (GLB, Pivot Painter textures, table); instances of a variant share one mesh and one clip."""
    project = data / "projects" / "small.sylva"
    forest = sylva.load_project(project).build_forest(wind=True)
    out = tmp_path / "py" / "forest.glb"
    out.parent.mkdir()
    written = forest.export(out, wind=True, bones=16, clip_length=2.0)
    assert written[0] == str(out)
    assert any(w.endswith(".wind.csv") for w in written)
    assert any(w.endswith("_pivot_index.exr") for w in written)
    by_cli = tmp_path / "cli" / "forest.glb"
    by_cli.parent.mkdir()
    cli("forest", project, "-o", by_cli, "--wind", "--bones", 16, "--clip-length", 2)
    for name in [pathlib.Path(w).name for w in written]:
        assert (by_cli.parent / name).read_bytes() == (out.parent / name).read_bytes(), name
    doc = glb_json(out)
    (anim,) = doc["animations"]
    assert anim["name"] == "wind"
    skins = doc["skins"]
    drawn = sum(1 for t in forest if len(t.mesh.positions))  # a tree pruned away: no rig
    assert len(skins) == drawn > 1, "one skin per tree"
    # Instances of one variant: one mesh and the same clip accessors for each of them.
    meshes = {n["mesh"] for n in doc["nodes"] if "skin" in n}
    assert len(meshes) < drawn, "variants' instances share their mesh"
    # The project's wind is the default; keyword arguments win over it.
    p = sylva.load_project(project)
    p.wind = {"strength": 1.5}
    windy = p.build_forest(wind=True)
    windy.export(tmp_path / "windy.glb", wind=True, bones=16, clip_length=2.0)
    assert glb_json(tmp_path / "windy.glb")["asset"]["extras"]["sylva_wind"]["strength"] == 1.5
    windy.export(tmp_path / "calm.glb", wind=True, bones=16, clip_length=2.0, strength=0.2)
    assert glb_json(tmp_path / "calm.glb")["asset"]["extras"]["sylva_wind"]["strength"] == 0.2
    with pytest.raises(ValueError, match="build_forest"):
        sylva.load_project(project).build_forest().export(tmp_path / "x.glb", wind=True)
    with pytest.raises(ValueError, match="wind=True"):
        forest.export(tmp_path / "x.glb", strength=1)
