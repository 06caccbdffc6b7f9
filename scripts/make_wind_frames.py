"""Frames of a tree in wind drawn by Sylva's own viewport (docs/wind.md), an editor script:

  xvfb-run -a -s '-screen 0 1400x1000x24' build/release/app/editor/sylva --discard-autosave \
      --script scripts/make_wind_frames.py presets/english-oak.json

Writes $SYLVA_WIND_FRAMES (default /tmp/sylva-wind) /frame-NN.png: the tree at rest, then
FRAMES frames STEP seconds apart of the frozen wind clock (window.set_wind_time) with View >
Wind on, strength 1.5 and gustiness 0.5 blowing along +X (to the right of the first view);
and close-up-rest.png / close-up-wind.png of the crown's lower forks (SYLVA_WIND_HEIGHT: the
tree's height in metres, which places that view). The strip and the GIF
are put together with ImageMagick (docs/wind.md says how).
"""
import os

import sylva

OUT = os.environ.get("SYLVA_WIND_FRAMES", "/tmp/sylva-wind")
FRAMES = int(os.environ.get("SYLVA_WIND_COUNT", "6"))
STEP = float(os.environ.get("SYLVA_WIND_STEP", "0.4"))
os.makedirs(OUT, exist_ok=True)

doc = sylva.document()
win = sylva.window()
win.resize(1900, 1050)
doc.set_wind(direction=(1.0, 0.0, 0.0), strength=1.5, gustiness=0.5)
sylva.wait(0.5)
height = float(os.environ.get("SYLVA_WIND_HEIGHT", "14"))  # the tree's, metres
# From the front, the wind blowing to the right.
win.look_from((0.0, 0.5 * height, 1.9 * height), (0.0, 0.5 * height, 0.0))

win.set_view_wind(False)
win.screenshot(os.path.join(OUT, "frame-rest.png"), viewport_only=True)
win.set_view_wind(True)
for i in range(FRAMES):
    win.set_wind_time(i * STEP)
    win.screenshot(os.path.join(OUT, f"frame-{i:02d}.png"), viewport_only=True)

# The lower forks, near: where a rig or a shader that moves children apart from their parent
# tears the bark, and where leaves leave their twigs.
fork = (0.0, 0.41 * height, 0.0)
win.look_from((0.12 * height, 0.47 * height, 0.55 * height), fork)
win.set_view_wind(False)
win.screenshot(os.path.join(OUT, "close-up-rest.png"), viewport_only=True)
win.set_view_wind(True)
win.set_wind_time(STEP)
win.screenshot(os.path.join(OUT, "close-up-wind.png"), viewport_only=True)
win.set_view_wind(False)
sylva.quit(0)
