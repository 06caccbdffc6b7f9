# The species graph through the script API, as a pipeline script tunes a species: the graph,
# nodes added, connected and removed, a refused connection's reason, the grammar with its
# diagnostics (the edit is kept), the live preview's time and which nodes re-ran, and undo back
# to the exact project. Run by run_scripts.sh through `sylva --script`.
import sylva

doc = sylva.document()
win = sylva.window()
original = doc.serialized()

g = doc.graph("alder")
assert g["output"] == "mesh", g
assert [n["id"] for n in g["nodes"]] == ["grow", "mesh"], g
assert g["nodes"][1]["inputs"] == ["grow"], g

# No preview has run yet (the species editor is closed): no time, rather than 0 ("instant").
assert doc.preview_ms() is None, doc.preview_ms()

win.edit_species("alder")
assert win.wait_for_preview(120)
first = doc.preview_stats()
assert first["nodes"]["grow"][0] and first["nodes"]["mesh"][0], first

# Nodes: add, connect (the single input of mesh is replaced), remove; one step each.
leaves = doc.add_node("alder", "leaves", {"size": 0.1}, position=(250, 120))
assert leaves == "leaves", leaves
doc.connect("alder", "grow", "leaves")
doc.connect("alder", "leaves", "mesh")
g = doc.graph("alder")
assert [n for n in g["nodes"] if n["id"] == "mesh"][0]["inputs"] == ["leaves"], g
assert doc.undo_texts()[-3:] == ["Add node leaves", "Connect grow to leaves",
                                 "Connect leaves to mesh"], doc.undo_texts()
# Refused edits raise ValueError with the reason and change nothing.
before = doc.serialized()
for bad, expect in [
    (lambda: doc.connect("alder", "mesh", "grow"), "takes no input"),
    (lambda: doc.add_node("alder", "no_such_node"), "unknown node type 'no_such_node'"),
    (lambda: doc.remove_node("alder", "mesh"), "output"),
    (lambda: doc.set_param("alder", "leaves.size", -1), "size must be in"),
]:
    try:
        bad()
        raise AssertionError("accepted: " + expect)
    except ValueError as e:
        assert expect in str(e), (expect, str(e))
assert doc.serialized() == before

# A parameter of the last node: the preview re-runs only the mesher.
assert win.wait_for_preview(120)
doc.set_param("alder", "mesh.resolution", 5)
assert win.wait_for_preview(120)
sylva.wait(0.2)
st = doc.preview_stats()
assert st["nodes"]["mesh"][0] and not st["nodes"]["grow"][0], st
assert doc.preview_ms() > 0, doc.preview_ms()
# Every stage of edit → screen is reported; on screen is the result, its frame, the present
# and the wait before the frame (to rounding).
sylva.wait(0.2)
st = doc.preview_stats()
for key in ("upload_ms", "frame_ms", "present_ms", "wait_ms"):
    assert st[key] >= 0.0, (key, st)
assert st["frame_ms"] > 0.0, st
assert abs(st["edit_to_result_ms"] + st["frame_ms"] + st["present_ms"] + st["wait_ms"]
           - st["edit_to_screen_ms"]) < 0.5 or st["wait_ms"] == 0.0, st

# The grammar: diagnostics as (line, column, message); the edit is kept, as in the editor.
text = doc.grammar("alder", "grow")
diagnostics = doc.set_grammar("alder", "grow", "axiom: F\nF -> F[+F\n")
assert diagnostics == [(2, 7, "unbalanced brackets: '[' is never closed in the successor")], diagnostics
assert doc.grammar("alder", "grow") == "axiom: F\nF -> F[+F\n"
assert doc.set_grammar("alder", "grow", text) == []

while doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == original
print("api_species: ok")
sylva.quit(0)
