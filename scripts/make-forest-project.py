#!/usr/bin/env python3
"""Writes a benchmark forest project of N trees: the six library species of
resources/demo/bench-10000.sylva in equal shares over a square whose side grows with sqrt(N)
(the same density, one tree per 100 m^2), with the demo's wall and boulder and camera.
usage: make-forest-project.py N OUT.sylva
"""
import json
import math
import os
import sys

if len(sys.argv) != 3:
    raise SystemExit(__doc__)
n, out = int(sys.argv[1]), os.path.abspath(sys.argv[2])
root = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
demo = os.path.join(root, "resources", "demo")
species = ["english-oak", "silver-birch", "european-beech", "norway-maple", "scots-pine",
           "norway-spruce"]
rel = lambda p: os.path.relpath(p, os.path.dirname(out))
half = 10.0 * math.sqrt(n) / 2.0
counts = {s: n // len(species) + (1 if i < n % len(species) else 0) for i, s in enumerate(species)}
project = {
    "format": "sylva-project",
    "format_version": 1,
    "seed": 1,
    "species": [{"name": s, "file": rel(os.path.join(root, "presets", s + ".json"))} for s in species],
    "domains": [{"shape": "rectangle", "min": [-half, -half], "max": [half, half], "counts": counts}],
    "instances": [],
    "obstacles": [
        {"file": rel(os.path.join(demo, "meshes", "wall.obj")), "translate": [0, 0, -20],
         "rotate": [0, 0, 0], "scale": [4, 2, 1]},
        {"file": rel(os.path.join(demo, "meshes", "boulder.obj")), "translate": [30, 0, 30],
         "rotate": [0, 0, 0], "scale": [3, 3, 3]},
    ],
    "camera": {"position": [0, 30, 150], "target": [0, 0, 0]},
    "light": {"direction": [0.3, -1, 0.2]},
}
os.makedirs(os.path.dirname(out), exist_ok=True)
with open(out, "w") as f:
    json.dump(project, f, indent=2)
    f.write("\n")
