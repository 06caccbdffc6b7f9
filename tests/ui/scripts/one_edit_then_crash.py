# The first edit after opening, alone: it must reach the recovery copy a few seconds later like
# any other (it used to wait for the 2-minute timer: the idle timer was started only when the
# document already read as modified, which the first edit's change signal arrives before).
import os, signal, sylva
doc = sylva.document()
assert not doc.modified
doc.add_tree("alder", (6, 0, -2), seed=91)
with open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.sylva", "w", encoding="utf-8") as f:
    f.write(doc.serialized())
sylva.wait(5)  # the idle autosave fires 3 s after the edit
os.kill(os.getpid(), signal.SIGKILL)
