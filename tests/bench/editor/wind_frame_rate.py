# Frames per second of the editor's viewport with View > Wind off and on, in the same run
# (issue 31; run on demand, not by ctest):
#   xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/editor/sylva --discard-autosave \
#       --script tests/bench/editor/wind_frame_rate.py resources/demo/forest.sylva
# Two cameras: orbiting as frame_rate.py's does (window.measure_frames: a software renderer
# draws moving frames at reduced resolution), and still (orbit=0: every frame drawn again at
# full resolution, which is what View > Wind asks for while the view rests). The wind clock
# runs with the wall clock, so every frame with wind on draws a new pose. Each figure is printed with the
# machine's load average (/proc/loadavg) at the time: other processes share the CPU that Mesa
# llvmpipe rasterises on, and the figures move with them. Off and on alternate three times so
# that a change in the load shows in both.
import time

import sylva

doc = sylva.document()
win = sylva.window()
win.resize(1400, 900)
stats = doc.generate()
if hasattr(win, "wait_view_lod"):
    win.wait_view_lod()
if doc.wind() is None:
    doc.set_wind(strength=1.0, gustiness=0.5)  # a strong wind: every element bends
sylva.wait(0.5)


def load():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def measure(label, orbit):
    if hasattr(win, "wait_view_lod"):
        win.wait_view_lod()
    win.measure_frames(5, orbit)  # warm up
    f = win.measure_frames(40, orbit)
    print(f"{doc.path.split('/')[-1]} {label}: {stats['trees']} trees, "
          f"{f['fps']:.1f} fps, {f['ms_per_frame']:.1f} ms/frame, "
          f"CPU {f['cpu_ms_per_frame']:.1f} ms (GUI thread {f['gui_cpu_ms_per_frame']:.1f} ms), "
          f"{f.get('triangles_drawn', '?')} triangles drawn; load average {load()}", flush=True)
    return f["fps"]


eye, target = doc.camera()
results = {}
win.set_wind_time(None)  # the wall clock: a new pose every frame
for round_ in range(3):
    for camera, orbit in (("orbiting", 4.0), ("still", 0.0)):
        for on in (False, True):
            win.set_view_wind(on)
            win.look_from(eye, target)
            label = f"{camera}, wind {'on' if on else 'off'}"
            results.setdefault(label, []).append(measure(label, orbit))
for label, values in results.items():
    values.sort()
    print(f"{label}: median {values[1]:.1f} fps [{values[0]:.1f}-{values[2]:.1f}]")
win.set_view_wind(False)
sylva.quit(0)
