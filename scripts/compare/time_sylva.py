#!/usr/bin/env python3
# Times the English oak per tree, warm, one thread, as docs/performance.md's issue-41 row:
# sylva.load_species(...).grow(seed).mesh with time.process_time, 3 warm-up trees, 12 seeds.
import sys, time, statistics, json
import sylva
sp = sylva.load_species(sys.argv[1] if len(sys.argv) > 1 else 'presets/english-oak.json')
n = int(sys.argv[2]) if len(sys.argv) > 2 else 12
ms, tris = [], []
for i in range(n + 3):
    t0 = time.process_time()
    m = sp.grow(1000 + i).mesh
    dt = time.process_time() - t0
    if i >= 3:
        ms.append(dt * 1000); tris.append(m.triangle_count)
med = statistics.median(ms); mt = statistics.median(tris)
print(json.dumps({"trees": len(ms), "median_cpu_ms": round(med, 3), "min_cpu_ms": round(min(ms), 3),
                  "median_triangles": mt, "triangles_per_second": round(mt / (med / 1000))}))
