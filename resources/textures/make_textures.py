#!/usr/bin/env python3
"""Generates Sylva's bark and leaf textures (PNG) procedurally; no dependencies beyond Python.

bark.png: 256x256 RGB, tiles in both directions (u around the branch, v along it).
leaf.png: 256x512 RGBA, a pointed leaf with veins; stem at the bottom (v = 0), alpha cut-out.
Run from anywhere: python3 make_textures.py  (writes next to this script). Deterministic.
"""
import math
import os
import random
import struct
import zlib


def write_png(path, width, height, rows, channels):
    color_type = 6 if channels == 4 else 2
    raw = b"".join(b"\x00" + bytes(row) for row in rows)

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def periodic_noise(rng, cells_x, cells_y):
    """Smooth value noise that tiles with the given number of cells."""
    grid = [[rng.random() for _ in range(cells_x)] for _ in range(cells_y)]

    def sample(u, v):
        x = (u % 1.0) * cells_x
        y = (v % 1.0) * cells_y
        x0, y0 = int(x), int(y)
        fx, fy = x - x0, y - y0
        fx = fx * fx * (3 - 2 * fx)
        fy = fy * fy * (3 - 2 * fy)
        x1, y1 = (x0 + 1) % cells_x, (y0 + 1) % cells_y
        a = grid[y0][x0] * (1 - fx) + grid[y0][x1] * fx
        b = grid[y1][x0] * (1 - fx) + grid[y1][x1] * fx
        return a * (1 - fy) + b * fy

    return sample


def bark(path, size=256):
    rng = random.Random(42)
    n1 = periodic_noise(rng, 8, 4)
    n2 = periodic_noise(rng, 32, 16)
    n3 = periodic_noise(rng, 64, 64)
    rows = []
    for y in range(size):
        v = y / size
        row = []
        for x in range(size):
            u = x / size
            # Vertical ridges whose phase wanders along v: furrowed bark.
            warp = 0.35 * n1(u, v) + 0.1 * n2(u, v)
            ridge = abs(math.sin(math.pi * (6 * u + 2 * warp)))
            ridge = ridge ** 0.6
            crack = 1.0 if n2(u * 1.0, v * 2.0) > 0.78 else 0.0
            shade = 0.45 + 0.45 * ridge + 0.15 * (n3(u, v) - 0.5) - 0.25 * crack * (1 - ridge)
            shade = max(0.05, min(1.0, shade))
            r = int(255 * min(1.0, 0.42 * shade + 0.04))
            g = int(255 * min(1.0, 0.31 * shade + 0.03))
            b = int(255 * min(1.0, 0.22 * shade + 0.02))
            row += [r, g, b]
        rows.append(row)
    write_png(path, size, size, rows, 3)


def leaf(path, width=256, height=512):
    rng = random.Random(7)
    n = periodic_noise(rng, 16, 32)
    rows = []
    for y in range(height):
        t = 1.0 - (y + 0.5) / height  # 0 at the bottom row (stem), 1 at the top (tip)
        row = []
        for x in range(width):
            s = (x + 0.5) / width * 2.0 - 1.0  # -1..1 across
            # Half width of the blade along its length: zero at stem and tip, widest at 40 %.
            blade = 0.0
            if 0.06 < t < 0.98:
                k = (t - 0.06) / 0.92
                blade = 0.95 * math.sin(math.pi * k ** 0.8) ** 0.9
            inside = abs(s) < blade
            stem = t <= 0.08 and abs(s) < 0.035
            if not inside and not stem:
                row += [40, 80, 30, 0]
                continue
            # Midrib and side veins at 45 degrees.
            vein = 0.0
            if abs(s) < 0.03:
                vein = 1.0
            else:
                phase = (t - 0.6 * abs(s)) * 14.0
                d = abs(phase - round(phase))
                if d < 0.06 and abs(s) < blade * 0.92:
                    vein = 0.6
            edge = min(1.0, (blade - abs(s)) / 0.08) if inside else 1.0
            shade = 0.75 + 0.2 * (n(x / width, y / height) - 0.5) + 0.1 * (1 - abs(s))
            shade *= 0.85 + 0.15 * edge
            r = 0.16 * shade + 0.25 * vein
            g = 0.42 * shade + 0.25 * vein
            b = 0.10 * shade + 0.12 * vein
            row += [int(255 * min(1.0, r)), int(255 * min(1.0, g)), int(255 * min(1.0, b)), 255]
        rows.append(row)
    write_png(path, width, height, rows, 4)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    bark(os.path.join(here, "bark.png"))
    leaf(os.path.join(here, "leaf.png"))
