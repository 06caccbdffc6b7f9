# Frames per second of the editor's viewport (run on demand, not by ctest), orbiting the view:
#   xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/editor/sylva \
#       --script tests/bench/editor/frame_rate.py resources/demo/alder-reference.sylva
# Prints fps, wall and CPU milliseconds per frame (the process, which includes Mesa llvmpipe's
# rasterizer threads, and the GUI thread), the trees drawn and the scene's triangles, from the
# project's camera and from three times as far; with the viewport's level of detail (issue 18)
# and without it (the same binary, window.set_view_lod(False)), and with the bark's back faces
# drawn (window.set_back_face_culling(False)); then the time from a released
# drag of the hand-placed tree to its re-adapted mesh on screen.
import statistics
import time

import sylva

doc = sylva.document()
win = sylva.window()
win.resize(1400, 900)
stats = doc.generate()
t0 = time.monotonic()
has_lod = hasattr(win, "wait_view_lod")  # an editor older than the viewport LOD has neither
if has_lod:
    win.wait_view_lod()  # the coarser levels are made on a worker, impostors at paint time
print(f"view LOD levels made in {time.monotonic() - t0:.1f} s")
sylva.wait(0.5)


def measure(label):
    if has_lod:
        win.wait_view_lod()
    win.measure_frames(5)  # warm up
    f = win.measure_frames(40)
    print(f"{doc.path.split('/')[-1]} {label}: {stats['trees']} trees, {f['triangles']} "
          f"triangles: {f['fps']:.1f} fps, {f['ms_per_frame']:.1f} ms/frame, "
          f"CPU {f['cpu_ms_per_frame']:.1f} ms (GUI thread {f['gui_cpu_ms_per_frame']:.1f} ms), "
          f"{f['trees_drawn']} trees drawn"
          + (f", {f['triangles_drawn']} triangles drawn, trees per level {f['trees_per_level']}"
             if "triangles_drawn" in f else ""))


eye, target = doc.camera()
far = tuple(t + 3.0 * (e - t) for e, t in zip(eye, target))
for view, where in (("project camera", eye), ("3x farther", far)):
    win.look_from(where, target)
    measure(view + (", LOD" if has_lod else ""))
    if has_lod:
        win.set_view_lod(False)
        win.look_from(where, target)
        measure(view + ", LOD off")
        win.set_view_lod(True)
    if hasattr(win, "set_back_face_culling"):  # the bark's back faces culled (the default)
        win.set_back_face_culling(False)
        win.look_from(where, target)
        measure(view + (", LOD" if has_lod else "") + ", back faces drawn")
        win.set_back_face_culling(True)
win.look_from(eye, target)
if has_lod:
    win.wait_view_lod()
trees = doc.trees()
if trees:
    tid = trees[0].id
    x, y, z = trees[0].position
    times, regrown = [], []
    for i in range(10):
        doc.set_tree(tid, position=(x + 0.05 * (i % 2), y, z))  # what a released drag pushes
        r = doc.generate()
        sylva.wait(0.2)
        times.append(win.last_update_ms())
        regrown.append(r["regrown"])
    print(f"released move -> re-adapted tree on screen: median {statistics.median(times):.1f} ms "
          f"[{min(times):.1f}-{max(times):.1f}], regrown {statistics.median(regrown):.0f}")
sylva.quit(0)
