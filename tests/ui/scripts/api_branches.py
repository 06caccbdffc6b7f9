# Issue #43: hand edits of single branches through the editor's document API. doc.branches
# lists a hand-placed tree's branches on stable ids; doc.edit_branch is one undo step each,
# bad input raises ValueError and changes nothing, undo gives back the exact bytes; pruning a
# branch lowers the forest's triangles, bending moves the branch's tip. Run by run_scripts.sh.
import math
import sylva

doc = sylva.document()
original = doc.serialized()
doc.generate()
tid = doc.trees()[0].id
branches = doc.branches(tid)
assert branches[0]["id"] == "0" and branches[0]["parent"] is None, branches[0]
assert all(b["parent"] is not None for b in branches[1:])
ids = [b["id"] for b in branches]
assert len(ids) == len(set(ids)) and len(ids) > 3, ids
limb = max((b for b in branches if b["order"] == 1), key=lambda b: b["length"])
before = doc.generate()

# Prune the longest limb: one undo step; the tree has fewer triangles and branches.
doc.edit_branch(tid, limb["id"], prune=True)
assert doc.undo_texts()[-1] == "Prune branch", doc.undo_texts()
assert doc.branch_edits(tid) == [{"branch": limb["id"], "prune": True}], doc.branch_edits(tid)
pruned = doc.generate()
assert pruned["triangles"] < before["triangles"], (pruned, before)
assert limb["id"] not in [b["id"] for b in doc.branches(tid)]
assert '"format_version": 3' in doc.serialized()

# prune=False clears it; bend it straight up instead, shorter: its tip moves, base -> tip is up.
doc.edit_branch(tid, limb["id"], prune=False, bend=(0, 1, 0), length=0.8)
bent = {b["id"]: b for b in doc.branches(tid)}[limb["id"]]
d = [t - b for t, b in zip(bent["tip"], bent["base"])]
n = math.sqrt(sum(x * x for x in d))
assert abs(d[1] / n - 1.0) < 1e-3, bent
assert abs(bent["length"] - 0.8 * limb["length"]) < 1e-3 * limb["length"], (bent, limb)
assert doc.branch_edits(tid) == [{"branch": limb["id"], "bend": (0.0, 1.0, 0.0),
                                  "length": doc.branch_edits(tid)[0]["length"]}]

# Bad input: ValueError, nothing changes.
state = doc.serialized()
for bad in [dict(length=30), dict(radius=0.0), dict(bend=(0, 0, 0))]:
    try:
        doc.edit_branch(tid, limb["id"], **bad)
        raise AssertionError("accepted %r" % bad)
    except ValueError as e:
        assert "out of range [0.05, 20]" in str(e) or "non-zero" in str(e), e
for tree, branch in [(tid, "0.999"), (987654, "0.1")]:
    try:
        doc.edit_branch(tree, branch, prune=True)
        raise AssertionError("accepted %r" % branch)
    except ValueError:
        pass
assert doc.serialized() == state
assert doc.generate()["orphaned_edits"] == 0

# Lock it: its geometry (bent, shortened) is kept through a regrowth from another seed.
doc.edit_branch(tid, limb["id"], lock=True)
assert doc.branch_edits(tid)[0]["lock"] and doc.branch_edits(tid)[0]["locked_nodes"] > 1
try:
    doc.edit_branch(tid, limb["id"], length=0.5)
    raise AssertionError("a locked branch changed")
except ValueError as e:
    assert "is locked" in str(e), e
seed = doc.tree(tid).seed
doc.set_tree(tid, seed=seed + 1)
kept = {b["id"]: b for b in doc.branches(tid)}[limb["id"]]
assert abs(kept["length"] - bent["length"]) < 1e-4 * bent["length"], (kept, bent)
assert all(abs(a - b) < 1e-4 for a, b in zip(
    [t - b for t, b in zip(kept["tip"], kept["base"])], d)), (kept, bent)
doc.undo()  # the seed
doc.edit_branch(tid, limb["id"], lock=False)
assert "lock" not in doc.branch_edits(tid)[0]

doc.clear_branch_edits(tid)
assert doc.branch_edits(tid) == []
assert doc.undo_texts()[-1] == "Clear branch edits"
while doc.serialized() != original and doc.undo_count() > 0:
    doc.undo()
assert doc.serialized() == original
print("api_branches.py: ok")
