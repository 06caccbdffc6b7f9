# After one_edit_then_crash.py: --restore brought back its single edit.
import os, sylva
doc = sylva.document()
expected = open(os.environ["SYLVA_TEST_OUT"] + "/before-crash.sylva", encoding="utf-8").read()
assert doc.serialized() == expected, "the restored project differs"
assert doc.modified, "restored edits must count as unsaved"
assert any(t.seed == 91 for t in doc.trees())
print("check_one_edit_restored: ok")
