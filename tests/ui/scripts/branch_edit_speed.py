# One hand-placed tree of the library: a branch edit to its result and to the screen, N bends
# of its limbs through doc.edit_branch (docs/editor.md#the-branch-tool). SP (species, default
# european-beech: 3,661 internodes from seed 11; norway-spruce: 9,843), SEED (11), N (12), CAM
# (the camera's eye, "x,y,z", default 0,8,30: the whole tree in view; 0,6,12: the crown fills
# it), PARAMS (species parameters set first, "node.param=value,...": the beech with
# "crown.segment_length=0.125,crown.attractors=9000" has 5,046 internodes).
import os, statistics, sylva
doc = sylva.document(); win = sylva.window()
win.resize(1400, 900)
doc.new()
species = os.environ.get("SP", "european-beech")
doc.add_species(species, os.path.join(os.environ["SYLVA_PRESETS_DIR"], species + ".json"))
for kv in filter(None, os.environ.get("PARAMS", "").split(",")):
    key, value = kv.split("=")
    doc.set_param(species, key, float(value) if "." in value else int(value))
tid = doc.add_tree(species, (0, 0, 0), seed=int(os.environ.get("SEED", "11")))
doc.set_camera(tuple(float(x) for x in os.environ.get("CAM","0,8,30").split(",")), (0, 7, 0))
st0 = doc.generate(); sylva.wait(1.0)
print("triangles", st0["triangles"])
br = doc.branches(tid)
print(species, "branches", len(br))
limbs = [b for b in br if b["order"] == 1]
rows = []
for i in range(int(os.environ.get("N", "12"))):
    limb = limbs[i % len(limbs)]
    doc.edit_branch(tid, limb["id"], bend=[(1,1,0),(1,0.5,0),(0,1,1),(1,1,1)][i % 4])
    st = doc.generate()
    sylva.wait(0.5)
    t = st["timings_ms"]
    rows.append((st["ms"], t.get("trees_generate", 0), t.get("trees_mesh", 0),
                 st["edit_to_result_ms"], win.last_update_ms()))
    print("edit %d: build %.1f ms (edits applied %.1f, mesh %.1f), edit to result %.1f ms, "
          "edit to screen %.1f ms (regrown %d)" % (i, *rows[-1], st["regrown"]))
med = [statistics.median(c) for c in zip(*rows)]
print("median of %d: build %.1f ms (edits applied %.1f, mesh %.1f), edit to result %.1f ms, "
      "edit to screen %.1f ms [%.1f-%.1f]" % (len(rows), *med, min(r[4] for r in rows),
                                            max(r[4] for r in rows)))
f = win.measure_frames(10, 0.0)
print("frame ms %.1f triangles %d" % (f["ms_per_frame"], f["triangles"]))
sylva.quit(0)
