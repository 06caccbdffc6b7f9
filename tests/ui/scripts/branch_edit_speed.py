# One hand-placed tree of the library (about 5,000 internodes): edit to result and to screen.
import os, sys, sylva
doc = sylva.document(); win = sylva.window()
win.resize(1400, 900)
doc.new()
species = os.environ.get("SP", "english-oak")
doc.add_species(species, os.path.join(os.environ["SYLVA_PRESETS_DIR"], species + ".json"))
tid = doc.add_tree(species, (0, 0, 0), seed=int(os.environ.get("SEED", "11")))
doc.set_camera((0, 8, 30), (0, 7, 0))
doc.generate(); sylva.wait(1.0)
br = doc.branches(tid)
print(species, "branches", len(br))
limbs = [b for b in br if b["order"] == 1]
res = []
for i in range(8):
    limb = limbs[i % len(limbs)]
    doc.edit_branch(tid, limb["id"], bend=[(1,1,0),(1,0.5,0),(0,1,1),(1,1,1)][i % 4])
    st = doc.generate()
    sylva.wait(0.5)
    res.append((st["ms"], st["edit_to_result_ms"], win.last_update_ms()))
    print(st["timings_ms"]); print("edit %d: build %.1f ms, edit to result %.1f ms, edit to screen %.1f ms (regrown %d)" % (i, st["ms"], st["edit_to_result_ms"], win.last_update_ms(), st["regrown"]))
f = win.measure_frames(10, 0.0)
print("frame ms %.1f triangles %d" % (f["ms_per_frame"], f["triangles"]))
sylva.quit(0)
