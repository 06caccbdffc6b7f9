# Large forests in the editor's viewport (issue #32), run on demand, not by ctest:
#   xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/editor/sylva --discard-autosave \
#       --script tests/bench/editor/forest_scale.py resources/demo/bench-10000.sylva
# The editor restores its saved view settings (View ▸ Wind sways every tree and redraws all the
# time): for comparable figures run it with its own settings, XDG_CONFIG_HOME=$(mktemp -d).
# Prints the time to generate and to make the view's levels and impostors, then frames per
# second from the project camera (measure_frames turns the view a little each frame), the trees per level of
# detail and the process' memory (VmRSS, VmHWM).
import time

import sylva


def memory():
    fields = {}
    with open("/proc/self/status") as f:
        for line in f:
            key, _, value = line.partition(":")
            if key in ("VmRSS", "VmHWM"):
                fields[key] = int(value.split()[0]) // 1024
    return f"RSS {fields.get('VmRSS')} MiB (peak {fields.get('VmHWM')} MiB)"


doc = sylva.document()
win = sylva.window()
win.resize(1400, 900)
t0 = time.monotonic()
stats = doc.generate()
t1 = time.monotonic()
win.wait_view_lod()
t2 = time.monotonic()
# The editor generates the project while it opens, before the script runs: doc.generate() may
# find it done, so the generation's own time is its `ms`, not the wait here.
print(f"{doc.path.split('/')[-1]}: {stats['trees']} trees generated in {stats['ms'] / 1000:.1f} s "
      f"(waited {t1 - t0:.1f} s here), "
      f"view levels and impostors in {t2 - t1:.1f} s; {memory()}")
eye, target = doc.camera()
win.look_from(eye, target)
win.wait_view_lod()
win.measure_frames(3)
for label in ("project camera", "project camera again"):
    f = win.measure_frames(20)
    print(f"{label}: {f['fps']:.1f} fps, {f['ms_per_frame']:.1f} ms/frame, CPU "
          f"{f['cpu_ms_per_frame']:.1f} ms (GUI {f['gui_cpu_ms_per_frame']:.1f}), "
          f"{f['trees_drawn']} trees drawn, {f.get('triangles_drawn')} triangles, per level "
          f"{f.get('trees_per_level')} (triangles {f.get('triangles_per_level')}); "
          f"{memory()}")
