# After the crash: --restore brought back every edit up to the last autosave.
import os, sylva
doc = sylva.document()
expected = open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.sylva", encoding="utf-8").read()
assert doc.serialized() == expected, "the restored project differs"
assert doc.modified, "restored edits must count as unsaved"
assert doc.path.endswith("alder-reference.sylva"), doc.path
assert any(t.seed == 77 for t in doc.trees())
assert doc.seed == 4242
# The same forest as before the crash (at seed 4242: 43 trees, the two hand-placed ones and the
# domain's 42 less the one they stand on).
trees = int(open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.trees").read())
assert doc.generate()["trees"] == trees, (trees, "before the crash")
assert trees == 43, trees
print("check_restored: ok")
