# The species editor's live preview, edit → new tree on screen (run on demand, not by ctest):
#   xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/editor/sylva \
#       --script tests/bench/editor/species_preview.py resources/demo/alder-reference.sylva
# Adds a 20,000-segment species with leaves (tests/bench/editor/species/bench-20k.json), opens
# it in the species editor and, N times each, edits a parameter of the last node (leaf_scale,
# tube resolution) and of the generator (the grammar's angle): the median and range of the time
# from the edit to the preview's new mesh drawn (doc.preview_ms()), and which nodes re-ran; first
# with the bark's back faces drawn, then culled (the default).
import os
import statistics
import sylva

N = 12
doc = sylva.document()
win = sylva.window()
here = os.path.dirname(os.path.abspath(__file__))
doc.add_species("bench20k", os.path.join(here, "species", "bench-20k.json"))
win.resize(1600, 1000)
win.edit_species("bench20k")
win.wait_for_preview(120)
sylva.wait(0.5)


def measure(label, edit):
    times, results, evals, uploads, frames, presents, waits = [], [], [], [], [], [], []
    for i in range(N):
        edit(i)
        win.wait_for_preview(120)
        sylva.wait(0.12)  # the frame is drawn; preview_ms() is set when it is on screen
        times.append(doc.preview_ms())
        st = doc.preview_stats()
        results.append(st["edit_to_result_ms"])
        evals.append(st["evaluate_ms"])
        uploads.append(st.get("upload_ms", 0.0))
        frames.append(st.get("frame_ms", 0.0))
        presents.append(st.get("present_ms", 0.0))
        waits.append(st.get("wait_ms", 0.0))
    ran = [k for k, v in st["nodes"].items() if v[0]]
    print(f"{label:30s} edit→screen {statistics.median(times):7.1f} ms "
          f"[{min(times):.1f}-{max(times):.1f}]  edit→mesh {statistics.median(results):6.1f} ms"
          f"  evaluation {statistics.median(evals):6.1f} ms  upload {statistics.median(uploads):5.1f} ms"
          f"  frame {statistics.median(frames):5.1f} ms  present {statistics.median(presents):4.1f} ms  wait {statistics.median(waits):4.1f} ms  re-ran {','.join(ran)}")


for cull in (False, True) if hasattr(win, "set_back_face_culling") else (True,):
    if hasattr(win, "set_back_face_culling"):
        win.set_back_face_culling(cull)
        print("bark back faces " + ("culled (the default)" if cull else "drawn"))
    measure("leaf_scale (last node)", lambda i: doc.set_param("bench20k", "mesh.leaf_scale", 1.0 + 0.05 * (i + 1)))
    measure("tube resolution (last node)", lambda i: doc.set_param("bench20k", "mesh.resolution", 5 + i % 2))
    measure("grammar angle (generator)", lambda i: doc.set_param("bench20k", "grow.angle", 26.0 + i))
sylva.quit(0)
