# The artist's day (issue #40), end to end: real X events (xdotool) where an artist uses the mouse,
# the script API for the rest. Run by artists_day.sh through `sylva --script` under Xvfb, on the
# library project first:
#   1. every species file in presets/ (listed, so a new species or node type is covered without
#      editing this test) opens in the Species Editor; its preview finishes, every node of its
#      graph evaluated, the pane draws that species' own new mesh (not the one before), and one
#      parameter changed changes what the pane shows;
# then on the showcase demo (forest.sylva):
#   2. an upward orbit drag keeps the eye above the ground; Place and Brush (tool bar untouched:
#      one species) plant trees, a Move drag moves one; a failed generation stays in the status
#      bar after a preview's message; projects with a missing mesh and a broken species file do
#      not replace the document; undo gives back the opened bytes; the window is grabbed.
import glob
import json
import os
import subprocess
import time

import sylva

OUT = os.environ["SYLVA_TEST_OUT"]
SRC = os.environ["SYLVA_SOURCE_DIR"]
doc = sylva.document()
win = sylva.window()
win.resize(1500, 950)
started = time.time()


def xdo(*args, pause=0.15):
    subprocess.run(["xdotool", *[str(a) for a in args]], check=True)
    sylva.wait(pause)


def stem(path):
    return os.path.splitext(os.path.basename(path))[0]


# --- 1. every species of presets/ in the Species Editor ------------------------------------
doc.open(os.path.join(SRC, "resources/demo/library.sylva"))
library_bytes = doc.serialized()
known = set(doc.species())
presets = sorted(glob.glob(os.path.join(SRC, "presets", "*.json")))
assert len(presets) >= 12, presets
for path in presets:
    if stem(path) not in known:
        doc.add_species(stem(path), path)

previous_hash = None
for path in presets:
    name = stem(path)
    win.edit_species(name)
    ok = win.wait_for_preview(180)
    st = doc.preview_stats()
    assert ok and st["error"] is None, (name, st["error"], st["error_node"])
    assert st["species"] == name, (name, st["species"])
    graph = doc.graph(name)
    for node in graph["nodes"]:
        run = st["nodes"].get(node["id"])
        assert run is not None and run[2] >= 1, (name, node["id"], st["nodes"])
    assert st["triangles"] > 0, (name, st)
    assert st["shown_is_result"], (name, "the pane does not draw this species' mesh")
    assert st["shown_hash"] != previous_hash, (name, "the pane still shows the previous tree")
    assert doc.preview_ms() is not None and doc.preview_ms() > 0, (name, doc.preview_ms())
    if name in ("english-oak", "european-beech", "norway-maple"):
        win.screenshot(os.path.join(OUT, "species_%s.png" % name))

    # One parameter changed changes what the pane shows: the first number, from the output node
    # back, whose change the node accepts and which changes the tree.
    before = st["shown_hash"]
    changed = False
    order = [graph["output"]] + [n["id"] for n in reversed(graph["nodes"])
                                 if n["id"] != graph["output"]]
    types = {n["id"]: n["type"] for n in graph["nodes"]}
    tries = 0
    for node_id in order:
        for key in sorted(sylva.node_types()[types[node_id]]):
            try:
                value = doc.get_param(name, "%s.%s" % (node_id, key))
            except ValueError:
                continue
            if isinstance(value, bool) or not isinstance(value, (int, float)) or value == 0:
                continue
            new = value + 1 if isinstance(value, int) else value * 1.15
            steps = doc.undo_count()
            try:
                doc.set_param(name, "%s.%s" % (node_id, key), new)
            except ValueError:
                continue
            tries += 1
            ok = win.wait_for_preview(180)
            after = doc.preview_stats()
            changed = ok and after["shown_is_result"] and after["shown_hash"] != before
            while doc.undo_count() > steps:
                doc.undo()
            if changed or tries >= 6:
                break
        if changed or tries >= 6:
            break
    assert changed, (name, "no parameter change changed the preview")
    assert win.wait_for_preview(180), name
    previous_hash = doc.preview_stats()["shown_hash"]

# A species whose preview fails: the pane says so and never shows the previous species' tree;
# Messages has the node's message; no time is reported; wait_for_preview says False.
failing = os.path.join(OUT, "failing.json")
with open(failing, "w") as f:
    json.dump({"format": "sylva-species", "format_version": 1, "name": "failing",
               "graph": {"nodes": [
                   {"id": "grow", "type": "lsystem",
                    "params": {"grammar": "generations: 8\naxiom: F\nF -> FF[+F][-F]\n",
                               "symbol_limit": 50}},
                   {"id": "mesh", "type": "tube_mesh", "inputs": ["grow"]}],
                   "output": "mesh"}}, f)
doc.add_species("failing", failing)
win.edit_species("failing")
assert not win.wait_for_preview(180), "a failed preview reported success"
st = doc.preview_stats()
assert st["error"] and st["error_node"] == "grow", st
assert st["species"] == "failing" and not st["shown_is_result"], st
assert st["shown_hash"] == 1469598103934665603, "the pane still draws another species' tree"
assert doc.preview_ms() is None, doc.preview_ms()
win.screenshot(os.path.join(OUT, "species_failed.png"))
assert any("failing" in m and "grow" in m for m in win.messages()), win.messages()[-3:]

while doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == library_bytes, "undo did not give back the library project"
print("artist's day: %d species previewed, each changed by a parameter (%.0f s)"
      % (len(presets), time.time() - started))

# --- 2. the showcase demo --------------------------------------------------------------------
demo = os.path.join(SRC, "resources/demo/forest.sylva")
doc.open(demo)
doc.generate()
opened = doc.serialized()
win.set_tool("select")
sylva.wait(0.5)

# Orbit: an upward drag from the opening view (13 px took the eye under the ground before).
eye, target = win.view_camera()
centre = win.project(*target)
assert centre is not None
cx, cy = centre
xdo("mousemove", cx, cy, "mousedown", 1)
for k in range(1, 9):
    xdo("mousemove", cx, cy - 10 * k, pause=0.05)
xdo("mouseup", 1)
eye, _ = win.view_camera()
assert eye[1] >= 0.29, ("the orbit took the eye under the ground", eye)
# Back to the opening view for the tools.
cam_eye, cam_target = doc.camera()
win.look_from(cam_eye, cam_target)
sylva.wait(0.3)

# Place: a click on the ground plants one tree there.
count = len(doc.trees())
spot = win.project(2.0, 0.0, 22.0)
assert spot is not None
xdo("mousemove", *spot)
win.set_tool("place")
xdo("click", 1)
doc.generate()
assert len(doc.trees()) == count + 1, "Place planted nothing"
placed = doc.trees()[-1]
assert abs(placed.position[0] - 2.0) < 1.0 and abs(placed.position[2] - 22.0) < 1.0, placed.position
# Saved with the decimals the Properties panel shows (tenths of a degree), not 17 digits.
saved = [t for t in json.loads(doc.serialized())["instances"] if t["id"] == placed.id][0]
assert len(repr(saved["rotation"]).split(".")[-1]) <= 1, saved["rotation"]

# A click in the sky plants nothing and says so.
sky = win.project(0.0, 60.0, -40.0)
if sky is not None:
    xdo("mousemove", *sky, "click", 1)
    assert len(doc.trees()) == count + 1, "a click in the sky planted a tree"
    assert "No ground" in win.status()[0], win.status()

# Brush with the tool bar untouched: every tree it paints is the tool bar's one species.
ids_before = {t.id for t in doc.trees()}
win.set_tool("brush")
a = win.project(-4.0, 0.0, 26.0)
b = win.project(4.0, 0.0, 26.0)
xdo("mousemove", *a, "mousedown", 1)
for k in range(1, 9):
    x = a[0] + (b[0] - a[0]) * k // 8
    y = a[1] + (b[1] - a[1]) * k // 8
    xdo("mousemove", x, y, pause=0.05)
xdo("mouseup", 1)
doc.generate()
painted = [t for t in doc.trees() if t.id not in ids_before]
assert painted, "the brush painted nothing"
assert len({t.species for t in painted}) == 1, sorted({t.species for t in painted})

# Move: drag the placed tree's trunk.
doc.select([placed.id])
win.set_tool("move")
doc.generate()
trunk = win.project(placed.position[0], 0.5, placed.position[2])
xdo("mousemove", *trunk, "mousedown", 1)
for k in range(1, 6):
    xdo("mousemove", trunk[0] + 8 * k, trunk[1], pause=0.05)
xdo("mouseup", 1)
doc.generate()
moved = doc.tree(placed.id)
assert moved.position != placed.position, "the Move drag moved nothing"
win.set_tool("select")

# A failed generation stays in the status bar even when a preview's message comes later.
win.edit_species("english-oak")
assert win.wait_for_preview(180)
rock = os.path.join(OUT, "rock.obj")
with open(rock, "w") as f:
    f.write("v 30 0 30\nv 31 0 30\nv 30 1 30\nv 30 0 31\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
doc.add_obstacle(rock)
doc.generate()
os.remove(rock)  # gone from under the project: the next generation fails
win.regenerate_all()
try:
    doc.generate()
    raise AssertionError("a missing obstacle mesh generated")
except ValueError:
    pass
doc.set_param("english-oak", "mesh.resolution", 7)
assert win.wait_for_preview(180)
assert "rock.obj" in win.status()[1], win.status()
doc.undo()  # the parameter
doc.undo()  # the obstacle
doc.generate()
assert win.status()[1] == "", win.status()

# A screenshot right after an edit shows that edit: it waits for the generation (it showed the
# forest before it, and Statistics disagreed with the Outliner).
doc.season = "autumn"
win.screenshot(os.path.join(OUT, "autumn.png"))
assert not win.generating(), "the screenshot did not wait for the edit's generation"
doc.undo()
doc.generate()

# Opening a project with a missing mesh or a broken species file leaves this one as it was.
edited = doc.serialized()
steps = doc.undo_count()
path = doc.path
with open(demo) as f:
    project = json.load(f)
base = os.path.dirname(demo)
for s in project["species"]:
    s["file"] = os.path.normpath(os.path.join(base, s["file"]))
for o in project["obstacles"]:
    o["file"] = os.path.normpath(os.path.join(base, o["file"]))
missing = json.loads(json.dumps(project))
missing["obstacles"][1]["file"] = os.path.join(OUT, "gone", "boulder.obj")
with open(os.path.join(OUT, "missingmesh.sylva"), "w") as f:
    json.dump(missing, f)
with open(os.path.join(OUT, "broken.json"), "w") as f:
    f.write('{ "format": "sylva-species",\n  "name": "broken",\n  "graph": [ }\n')
broken = json.loads(json.dumps(project))
broken["species"][0]["file"] = os.path.join(OUT, "broken.json")
with open(os.path.join(OUT, "brokenspecies.sylva"), "w") as f:
    json.dump(broken, f)
for name, error, expect in [("missingmesh.sylva", OSError, "boulder.obj"),
                            ("brokenspecies.sylva", ValueError, "broken.json:3:")]:
    try:
        doc.open(os.path.join(OUT, name))
        raise AssertionError(name + " opened")
    except error as e:
        assert expect in str(e), (name, str(e))
    assert doc.serialized() == edited and doc.path == path and doc.undo_count() == steps, name
    stats = doc.generate()
    assert stats["trees"] == len(doc.trees()), (name, stats["trees"], len(doc.trees()))

# Undo everything: the opened bytes.
while doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == opened, "undo did not give back the opened demo"
doc.generate()
win.screenshot(os.path.join(OUT, "artists_day.png"))
print("artist's day: ok in %.0f s" % (time.time() - started))
sylva.quit(0)
