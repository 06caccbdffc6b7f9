"""The open project's forest from its own camera, as a PNG of the viewport (docs/forest.md's
unique-vs-instanced picture): EDITOR tests/bench/editor/project_camera_shot.py PROJECT with
SHOT_OUT=out.png in the environment. Prints the generation's statistics."""
import os

import sylva

win = sylva.window()
doc = sylva.document()
win.resize(1900, 1150)
stats = doc.generate()
print("stats", stats)
position, target = doc.camera()
win.look_from(position, target)
win.wait_view_lod(timeout=300)
win.screenshot(os.environ["SHOT_OUT"], viewport_only=True)
sylva.quit(0)
