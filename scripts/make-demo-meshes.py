#!/usr/bin/env python3
"""Writes the demo project's obstacle meshes (resources/demo/meshes): a boulder (a noisy
UV sphere) and a garden wall (a finely subdivided box), each over 10,000 triangles, so the demo
exercises the Embree collision path at a realistic size. Deterministic; run once, files are
committed."""
import math
import os
import sys

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "resources", "demo", "meshes")
os.makedirs(out, exist_ok=True)


def write_obj(path, name, verts, faces):
    with open(path, "w") as f:
        f.write(f"# {name}: {len(verts)} vertices, {len(faces)} triangles (made by scripts/make-demo-meshes.py)\n")
        f.write(f"o {name}\n")
        for v in verts:
            f.write("v %.4f %.4f %.4f\n" % v)
        for a, b, c in faces:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


def boulder(rings=72, segments=72, radius=4.0):
    verts, faces = [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments
            # smooth deterministic bumps; flattened bottom half sits in the ground
            bump = 1 + 0.08 * math.sin(3 * phi + 2 * theta) + 0.05 * math.cos(5 * theta - phi)
            r = radius * bump
            x = r * math.sin(theta) * math.cos(phi)
            y = r * math.cos(theta) * 0.7
            z = r * math.sin(theta) * math.sin(phi)
            verts.append((x, y + 1.0, z))
    for i in range(rings):
        for j in range(segments):
            a = i * segments + j
            b = i * segments + (j + 1) % segments
            c = (i + 1) * segments + j
            d = (i + 1) * segments + (j + 1) % segments
            if i > 0:
                faces.append((a, c, b))
            if i < rings - 1:
                faces.append((b, c, d))
    return verts, faces


def wall(lo=(-10.0, 0.0, -0.3), hi=(10.0, 3.0, 0.3), n=40):
    verts, faces = [], []

    def quad_grid(origin, du, dv, nu, nv):
        base = len(verts)
        for i in range(nu + 1):
            for j in range(nv + 1):
                verts.append(tuple(origin[k] + du[k] * i / nu + dv[k] * j / nv for k in range(3)))
        for i in range(nu):
            for j in range(nv):
                a = base + i * (nv + 1) + j
                b = a + 1
                c = a + (nv + 1)
                d = c + 1
                faces.append((a, c, b))
                faces.append((b, c, d))

    (x0, y0, z0), (x1, y1, z1) = lo, hi
    sx, sy, sz = x1 - x0, y1 - y0, z1 - z0
    quad_grid((x0, y0, z1), (sx, 0, 0), (0, sy, 0), 4 * n, n)   # front
    quad_grid((x1, y0, z0), (-sx, 0, 0), (0, sy, 0), 4 * n, n)  # back
    quad_grid((x0, y1, z0), (sx, 0, 0), (0, 0, sz), 4 * n, 4)   # top
    quad_grid((x0, y0, z0), (0, 0, sz), (0, sy, 0), 4, n)      # left end
    quad_grid((x1, y0, z1), (0, 0, -sz), (0, sy, 0), 4, n)     # right end
    return verts, faces


for name, (v, f) in {"boulder": boulder(), "wall": wall()}.items():
    write_obj(os.path.join(out, name + ".obj"), name, v, f)
    print(f"{name}: {len(f)} triangles")
