# Real X11 input (xdotool), as an artist's mouse and keyboard give it: the events reach the 3D
# view's native OpenGL window, which hands them to the viewport widget; the keys must still reach
# the main window's shortcuts, and a Ctrl+drag draws the rubber band over the view and selects.
# Run by run_scripts.sh through `sylva --script` under Xvfb (no window manager: keys go to the
# window under the pointer unless the editor makes its main window the active one).
import subprocess

import sylva

doc = sylva.document()
win = sylva.window()
win.resize(1400, 900)
doc.generate()
sylva.wait(0.5)
original = doc.serialized()
win.set_tool("select")


def xdo(*args):
    subprocess.run(["xdotool", *[str(a) for a in args]], check=True)
    sylva.wait(0.3)


tid = doc.trees()[0].id
x, y, z = doc.trees()[0].position
trunk = win.project(x, y + 1.0, z)
assert trunk is not None, "the hand-placed tree is not in view"
tx, ty = trunk

# A click on the sky clears the selection; ] steps to the first tree (the viewport's own key).
sky = win.project(x, y + 40.0, z) or (tx, max(ty - 250, 60))
xdo("mousemove", sky[0], sky[1], "click", 1)
assert doc.selection() == [], doc.selection()
xdo("key", "bracketright")
assert doc.selection() == [tid], doc.selection()

# Delete and Ctrl+Z are the main window's shortcuts.
xdo("key", "Delete")
assert tid not in [t.id for t in doc.trees()], "Delete did not reach Edit > Delete"
xdo("key", "ctrl+z")
assert doc.serialized() == original, "Ctrl+Z did not restore the document"

# Ctrl+drag around the trunk: the rubber band, then the tree selected.
xdo("mousemove", tx - 60, ty - 50, "keydown", "ctrl", "mousedown", 1)
xdo("mousemove", tx, ty - 10)
xdo("mousemove", tx + 60, ty + 30)
xdo("mouseup", 1, "keyup", "ctrl")
assert doc.selection() == [tid], doc.selection()
print("real input: click, ], Delete, Ctrl+Z, Ctrl+drag: ok")
sylva.quit(0)
