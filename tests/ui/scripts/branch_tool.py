# Issue #43: the Branch tool from real X11 input (xdotool), as an artist's mouse and keyboard
# give it: a click selects the branch under the cursor (doc.selected_branch, Properties), a
# drag bends it about its base (one undo step), Delete prunes it (one step), and Ctrl+Z twice
# gives back the opened bytes. A screenshot of the editor with the branch selected is written to
# $SYLVA_TEST_OUT/branch_tool.png. Run by run_scripts.sh through `sylva --script` under Xvfb.
import os
import subprocess

import sylva

doc = sylva.document()
win = sylva.window()
win.resize(1400, 900)
doc.generate()
sylva.wait(0.5)
original = doc.serialized()
win.set_tool("branch")
assert win.tool() == "branch", win.tool()


def xdo(*args):
    subprocess.run(["xdotool", *[str(a) for a in args]], check=True)
    sylva.wait(0.3)


tid = doc.trees()[0].id
branches = {b["id"]: b for b in doc.branches(tid)}

# A pixel that shows a limb (order 1) or one of its branches: walk along each limb from its
# base to its tip on screen and ask what the tool would pick there (what is drawn).
target = None
for b in sorted(branches.values(), key=lambda b: -b["length"]):
    if b["order"] != 1:
        continue
    for f in (0.3, 0.45, 0.6, 0.2, 0.75):
        p = [bb + f * (tt - bb) for bb, tt in zip(b["base"], b["tip"])]
        pix = win.project(*p)
        if pix is None:
            continue
        hit = win.branch_at(*pix)
        if hit is not None and hit[0] == tid and branches[hit[1]]["order"] >= 1:
            target = (pix, hit[1])
            break
    if target:
        break
assert target is not None, "no limb of the tree is drawn where its skeleton projects"
(px, py), branch = target

# Click on the sky: nothing selected; click on the branch: it is selected.
x, y, z = doc.trees()[0].position
sky = win.project(x, y + 60.0, z) or (px, 60)
xdo("mousemove", sky[0], sky[1], "click", 1)
assert doc.selected_branch() is None, doc.selected_branch()
xdo("mousemove", px, py, "click", 1)
assert doc.selected_branch() == (tid, branch), (doc.selected_branch(), branch)
assert doc.selection() == [tid], doc.selection()
assert doc.serialized() == original, "a click changed the document"
out = os.environ.get("SYLVA_TEST_OUT", ".")
subprocess.run(["import", "-window", "root", os.path.join(out, "branch_tool.png")], check=True)

# Drag it: one undo step that bends it about its base; the new direction points towards the
# side it was dragged to.
steps = doc.undo_count()
base = branches[branch]["base"]
xdo("mousemove", px, py, "mousedown", 1)
xdo("mousemove", px + 30, py - 40)
xdo("mousemove", px + 70, py - 90)
xdo("mouseup", 1)
assert doc.undo_count() == steps + 1, doc.undo_texts()
edits = doc.branch_edits(tid)
assert len(edits) == 1 and edits[0]["branch"] == branch and "bend" in edits[0], edits
doc.generate()
sylva.wait(0.3)
bent = {b["id"]: b for b in doc.branches(tid)}[branch]
assert max(abs(a - b) for a, b in zip(bent["base"], base)) < 1e-3, (bent["base"], base)
assert max(abs(a - b) for a, b in zip(bent["tip"], branches[branch]["tip"])) > 0.05, bent
print("bend: last update %.1f ms" % win.last_update_ms())

# Delete prunes the selected branch (still selected after its bend): one step; the branch is
# gone from the tree, the tree stays.
assert doc.selected_branch() == (tid, branch), doc.selected_branch()
xdo("key", "Delete")
assert doc.undo_count() == steps + 2, doc.undo_texts()
assert doc.undo_texts()[-1] == "Prune branch", doc.undo_texts()
assert [t.id for t in doc.trees()] == [tid], "Delete removed the tree, not the branch"
doc.generate()
assert branch not in [b["id"] for b in doc.branches(tid)]

# Undo back to the opened bytes.
xdo("key", "ctrl+z")
xdo("key", "ctrl+z")
assert doc.serialized() == original, "Ctrl+Z twice did not restore the opened document"
print("branch tool: select %s, bend by drag, Delete, Ctrl+Z: ok" % branch)
sylva.quit(0)
