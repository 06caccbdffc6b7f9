# Edits, waits for the autosave a few seconds after the last edit (the window's timers keep
# running while the script waits), then dies with SIGKILL: no chance to save or clean up.
import os, signal, sylva
doc = sylva.document()
a = doc.add_tree("alder", (3, 0, 3), seed=77)
doc.set_tree(a, position=(3.5, 0, 3))
doc.seed = 4242
doc.set_param("ternary", "mesh.resolution", 4)
with open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.sylva", "w", encoding="utf-8") as f:
    f.write(doc.serialized())
with open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.trees", "w", encoding="utf-8") as f:
    f.write(str(doc.generate()["trees"]))
sylva.wait(5)  # the idle autosave fires 3 s after the last edit
os.kill(os.getpid(), signal.SIGKILL)
