# The sylva module's document API, driven as a pipeline script would: every edit is an undoable
# command, bad input raises the window's message and changes nothing, undo all gives back the
# exact project. Run by run_scripts.sh through `sylva --script`.
import os
import sylva

doc = sylva.document()
out = os.environ["SYLVA_TEST_OUT"]
assert doc.path.endswith("alder-reference.sylva"), doc.path
assert not doc.modified
original = doc.serialized()
assert doc.species() == ["alder", "ternary"], doc.species()
first = doc.generate()
assert first["trees"] == 42, first  # 42 domain trees, one displaced by the hand-placed alder

# Add, move, reseed, remove: one undo step each, with translatable names.
tid = doc.add_tree("ternary", (6, 0, 6), rotation=30, scale=1.2, seed=5)
assert doc.tree(tid).species == "ternary"
doc.set_tree(tid, position=(7, 0, 6))
doc.set_tree(tid, seed=6)
assert doc.undo_texts()[-3:] == ["Add tree", "Move tree", "Change tree seed"], doc.undo_texts()
stats = doc.generate()
# The new tree takes the place of the two domain trees it stands on (42 + 1 - 2); no other
# tree moves, so only the new one is grown.
assert stats["trees"] == 41, stats
assert stats["regrown"] == 1, stats

# The document's trees are `import sylva`'s sylva.Tree, and doc.project() is a sylva.Project
# (a copy) with the same trees, species, obstacles and domains.
assert isinstance(doc.tree(tid), sylva.Tree)
snapshot = doc.project()
assert isinstance(snapshot, sylva.Project)
assert snapshot.species == doc.species()
assert snapshot.domains == doc.domains() and snapshot.obstacles == doc.obstacles()
assert [(t.species, t.position, t.seed) for t in snapshot.trees()] == [
    (t.species, t.position, t.seed) for t in doc.trees()]
assert snapshot.tree_count == len(doc.trees())
grown = doc.add_tree("ternary", (8, 0, 8), growth=0.5)  # the same arguments as Project.add_tree
assert doc.tree(grown).growth == 0.5
doc.undo()
assert grown not in [t.id for t in doc.trees()]

# Bad input: the window's message, and nothing changed.
before = doc.serialized()
for bad, expect in [
    (lambda: doc.add_tree("baobab", (0, 0, 0)), "unknown species 'baobab'"),
    (lambda: doc.set_tree(tid, scale=0), "[0.01, 100]"),
    (lambda: doc.set_tree(9999, scale=2), "no tree with id 9999"),
    (lambda: doc.set_param("alder", "mesh.no_such", 1), "no_such"),
    (lambda: doc.add_tree("alder", (0, 0)), "three numbers"),
]:
    try:
        bad()
    except ValueError as e:
        assert expect in str(e), (expect, str(e))
    else:
        raise AssertionError("no ValueError for " + expect)
try:
    doc.open(os.path.join(out, "missing.sylva"))
except OSError as e:
    assert "missing.sylva" in str(e), str(e)
else:
    raise AssertionError("opening a missing file raised nothing")
assert doc.serialized() == before

# Species parameters: read, set (the species becomes inline), undo.
assert doc.get_param("alder", "mesh.resolution") == 8
doc.set_param("alder", "mesh.resolution", 5)
assert doc.get_param("alder", "mesh.resolution") == 5
assert "grammar" in doc.grammar("ternary", "grow") or doc.grammar("ternary", "grow")
doc.set_grammar("alder", "grow", doc.grammar("alder", "grow") + "\n# tuned\n")
assert doc.get_param("alder", "grow.grammar_file") is None
assert doc.undo_texts()[-1] == "Edit grammar"

# Obstacles, domains, settings.
wall = doc.obstacles()[0]["file"]
i = doc.add_obstacle(wall, translate=(10, 0, 10), rotate=(0, 45, 0))
doc.set_obstacle(i, scale=(2, 1, 1))
doc.set_domain(0, counts={"alder": 10, "ternary": 5})
doc.seed = 11
doc.set_camera((0, 30, 80), (0, 4, 0))
doc.set_light((0.2, -1, 0.1))
stats = doc.generate()
# The two hand-placed trees and the domain's 15, less the one a hand-placed tree stands on.
assert stats["trees"] == 1 + 1 + 15 - 1, stats

# Selection is not undoable; undo everything gives back the exact original project.
doc.select([tid])
assert doc.selection() == [tid]
steps = doc.undo_count()
while doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == original
assert not doc.modified
for _ in range(steps):
    doc.redo()
assert doc.modified
assert doc.tree(tid).position == (7.0, 0.0, 6.0)

# Save As elsewhere, reopen: byte for byte; export the forest.
saved = os.path.join(out, "scripted.sylva")
doc.save(saved)
assert not doc.modified and doc.path == saved
text = open(saved, encoding="utf-8").read()
doc.open(saved)
assert doc.serialized() == text
doc.export(os.path.join(out, "scripted.obj"))
assert os.path.getsize(os.path.join(out, "scripted.obj")) > 1000


def objects(path):
    with open(path, encoding="utf-8") as f:
        return sum(1 for line in f if line.startswith("o "))


# Export only the selection; and with the level of detail of a far viewport camera.
doc.select([doc.trees()[0].id])
doc.export(os.path.join(out, "selected.obj"), selection_only=True)
assert objects(os.path.join(out, "selected.obj")) == 1
assert objects(os.path.join(out, "scripted.obj")) == doc.generate()["trees"]
sylva.window().look_from((0, 300, 900), (0, 5, 0))
doc.export(os.path.join(out, "far.obj"), viewport_camera=True)
far, near = os.path.getsize(os.path.join(out, "far.obj")), os.path.getsize(os.path.join(out, "scripted.obj"))
assert far < near / 2, (far, near)
try:
    doc.select([])
    doc.export(os.path.join(out, "none.obj"), selection_only=True)
except OSError as e:
    assert "no hand-placed tree is selected" in str(e), str(e)
else:
    raise AssertionError("an empty selection exported")
sylva.window().screenshot(os.path.join(out, "script_window.png"))
print("api_edits: ok")
