# Edit-to-screen latency of the editor on a project (run on demand, not by ctest):
#   xvfb-run -a -s '-screen 0 1600x1000x24' build/release/app/editor/sylva \
#       --script tests/bench/editor/edit_latency.py resources/demo/alder-reference.sylva
# For each kind of one-tree edit it prints the median and range over N edits of: the
# generation (edit to new meshes ready) and edit to the frame on screen, with the trees
# regrown; then the same for a full regeneration (every tree regrown, caches dropped).
import statistics
import sylva

N = 15
doc = sylva.document()
win = sylva.window()
doc.generate()
sylva.wait(0.3)
tid = doc.trees()[0].id


def measure(label, edit):
    gen, screen, regrown = [], [], []
    for i in range(N):
        edit(i)
        stats = doc.generate()
        sylva.wait(0.15)  # the frame is drawn; last_update_ms() is set by it
        gen.append(stats["edit_to_result_ms"])
        screen.append(win.last_update_ms())
        regrown.append(stats["regrown"])
    print(f"{label:28s} result {statistics.median(gen):7.1f} ms "
          f"[{min(gen):.1f}-{max(gen):.1f}]  on screen {statistics.median(screen):7.1f} ms "
          f"[{min(screen):.1f}-{max(screen):.1f}]  regrown {statistics.median(regrown):.0f} "
          f"of {stats['trees']}")


measure("rotate the hand-placed tree", lambda i: doc.set_tree(tid, rotation=10.0 * (i + 1)))
measure("reseed the hand-placed tree", lambda i: doc.set_tree(tid, seed=100 + i))
measure("move the hand-placed tree", lambda i: doc.set_tree(tid, position=(2 + 0.1 * (i + 1), 0, -6.5)))
measure("full regeneration", lambda i: win.regenerate_all())
sylva.quit(0)
