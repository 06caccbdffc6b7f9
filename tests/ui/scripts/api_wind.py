# The editor's wind API (#31): doc.set_wind / doc.wind / doc.clear_wind are undoable edits of the
# project's "wind"; undo gives back the exact project; bad values raise with the allowed range.
# Run by run_scripts.sh through `sylva --script`.
import sylva

doc = sylva.document()
original = doc.serialized()
assert doc.wind() is None, doc.wind()
assert '"wind"' not in original

steps = doc.undo_count()
doc.set_wind(direction=(0, 0, -1), strength=1.5, gustiness=0.6)
assert doc.undo_count() == steps + 1
assert doc.undo_texts()[-1] == "Change wind", doc.undo_texts()
w = doc.wind()
assert w["direction"] == (0.0, 0.0, -1.0), w
assert abs(w["strength"] - 1.5) < 1e-6 and abs(w["gustiness"] - 0.6) < 1e-6, w
assert abs(w["frequency"] - 0.5) < 1e-6, w  # not given: the default
assert '"wind"' in doc.serialized()
assert doc.modified

# A setting not given keeps the project's.
doc.set_wind(strength=0.25)
w = doc.wind()
assert w["direction"] == (0.0, 0.0, -1.0) and abs(w["strength"] - 0.25) < 1e-6, w
windy = doc.serialized()

try:
    doc.set_wind(gustiness=1.5)
except ValueError as e:
    assert "gustiness" in str(e) and "1" in str(e), str(e)
else:
    raise AssertionError("a gustiness of 1.5 was accepted")
assert doc.serialized() == windy

doc.clear_wind()
assert doc.wind() is None
assert doc.serialized() == original
doc.undo()
assert doc.serialized() == windy
doc.undo()
doc.undo()
assert doc.serialized() == original, "undo did not give back the exact project"
assert doc.wind() is None
doc.redo()
assert doc.wind()["strength"] == 1.5
print("api_wind: ok")
