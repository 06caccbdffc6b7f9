# The window's wind API (#31): View > Wind from a script (win.set_view_wind / win.view_wind) and
# the deterministic wind clock (win.set_wind_time): a frozen time draws the same frame, two
# times draw two frames with wind on and one frame with it off; None lets the clock run again.
# Run by run_scripts.sh through `sylva --script`.
import hashlib
import os
import tempfile

import sylva

doc = sylva.document()
win = sylva.window()
doc.set_wind(strength=1.6, gustiness=0.6)
folder = tempfile.mkdtemp()


def shot(name):
    path = os.path.join(folder, name + ".png")
    win.screenshot(path, viewport_only=True)
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


assert win.view_wind() in (False, True)
# The coarser levels and impostors made first: a frame that draws a new one differs.
win.wait_view_lod()
shot("warm-up")
win.set_view_wind(True)
assert win.view_wind()
win.set_wind_time(0.5)
assert win.wind_time() == 0.5, win.wind_time()
a = shot("a")
assert shot("a2") == a, "the same wind time draws the same frame"
win.set_wind_time(1.7)
b = shot("b")
assert a != b, "two wind times draw two frames with View > Wind on"

win.set_view_wind(False)
assert not win.view_wind()
win.set_wind_time(0.5)
c = shot("c")
win.set_wind_time(1.7)
assert shot("d") == c, "with View > Wind off the wind time changes nothing"

try:
    win.set_wind_time(float("nan"))
except ValueError as e:
    assert "finite" in str(e), e
else:
    raise AssertionError("a NaN wind time was taken")

win.set_wind_time(None)  # the wall clock again, from where it was
t0 = win.wind_time()
sylva.wait(0.2)
assert win.wind_time() > t0, (t0, win.wind_time())
doc.undo()
sylva.quit(0)
