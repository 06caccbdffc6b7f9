#!/usr/bin/python3
"""Generates every texture Sylva ships: the species library's (presets/*.json) and the default
bark and leaf of species without textures of their own (resources/textures).

Every image is drawn here from noise and simple shapes; nothing is downloaded, so the PNGs are
ours to give away (CC0, see README.md). Deterministic: the same script writes the same bytes,
and the PNG writer is our own few lines (zlib level 9, no row filters) so that the bytes do not
depend on an imaging library's encoder or its version (they still depend on the zlib build:
Debian's zlib gives the committed bytes, zlib-ng would not).

  presets/textures/<species>_bark.png  256x256 RGB, tiles in both directions (u around the
                                       branch, v along it)
  presets/textures/<species>_leaf.png  RGBA cut-out card, stem at the bottom edge (v = 0); the
                                       conifers' are needle clusters (pine: long paired needles)
  presets/textures/<species>_leafcluster.png  1024x512 RGBA leaf cluster atlas: seven sprays and
                                       the single leaf, 4 x 2 tiles (the conifers': needle
                                       sprays drawn needle by needle; autumn: mixed tones)
  resources/textures/bark.png          256x256 RGB, the default bark
  resources/textures/leaf.png          256x512 RGBA, the default pointed leaf with veins

Needs Debian's python3-numpy. Run from anywhere: /usr/bin/python3 presets/textures/make_textures.py
(--library or --defaults writes only one of the two sets).
"""
import math
import os
import random
import struct
import sys
import zlib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULTS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "resources", "textures")
BARK = 256


# ----------------------------------------------------------------------------- PNG

def write_png(path, pixels):
    """Writes an 8-bit RGB or RGBA image (uint8 array, rows top to bottom) as PNG; a 2-D array
    is written as grey (roughness maps)."""
    if pixels.ndim == 2:
        pixels = pixels[..., None]
    h, w, channels = pixels.shape
    color_type = {1: 0, 3: 2, 4: 6}[channels]
    raw = b"".join(b"\x00" + pixels[y].tobytes() for y in range(h))

    def chunk(tag, data):
        return (struct.pack(">I", len(data)) + tag + data +
                struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, color_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def to_bytes(image):
    """0..1 floats → uint8, rounded."""
    return (np.clip(image, 0, 1) * 255 + 0.5).astype(np.uint8)


# ----------------------------------------------------------------------------- noise helpers

def noise(shape, sx, sy, seed):
    """Periodic smooth noise in 0..1: white noise low-passed in the frequency domain (so it
    tiles), sx and sy the feature size in pixels across (x) and along (y)."""
    rng = np.random.default_rng(seed)
    h, w = shape
    white = rng.standard_normal((h, w))
    ky = np.fft.fftfreq(h)[:, None]
    kx = np.fft.fftfreq(w)[None, :]
    filt = np.exp(-((kx * sx) ** 2 + (ky * sy) ** 2) * 2.0 * math.pi ** 2 / 4.0)
    out = np.real(np.fft.ifft2(np.fft.fft2(white) * filt))
    out -= out.min()
    return out / max(out.max(), 1e-9)


def cells(shape, count, seed, stretch=(1.0, 1.0)):
    """Periodic Worley noise: distance to the nearest and second nearest of \p count random
    points (wrapping), in pixels; stretch squeezes the cells across (x) and along (y)."""
    rng = np.random.default_rng(seed)
    h, w = shape
    pts = rng.random((count, 2)) * [w, h]
    yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
    d1 = np.full((h, w), 1e9, np.float32)
    d2 = np.full((h, w), 1e9, np.float32)
    ident = np.zeros((h, w), np.int32)
    for i, (px, py) in enumerate(pts):
        dx = np.abs(xx - px)
        dx = np.minimum(dx, w - dx) / stretch[0]
        dy = np.abs(yy - py)
        dy = np.minimum(dy, h - dy) / stretch[1]
        d = np.sqrt(dx * dx + dy * dy)
        closer = d < d1
        d2 = np.where(closer, d1, np.minimum(d2, d))
        ident = np.where(closer, i, ident)
        d1 = np.where(closer, d, d1)
    return d1, d2, ident


def colorize(shade, dark, light):
    """shade 0..1 → RGB between two sRGB colours (0..1)."""
    s = np.clip(shade, 0.0, 1.0)[..., None]
    return np.asarray(dark) * (1 - s) + np.asarray(light) * s


def save_rgb(name, rgb):
    write_png(os.path.join(HERE, name), to_bytes(rgb))


# ----------------------------------------------------------------------------- normal maps
# Every texture has a tangent-space normal map "<name>_normal.png" and a roughness map
# "<name>_roughness.png" beside it, derived from the height field the drawing below already
# makes (a bark's ridges and cracks, a leaf's veins and blade). Convention: OpenGL's (+Y up,
# like Blender and glTF): red = +u (right in the image), green = +v (up in the image, towards
# the top row: a bark's v along the branch, a leaf's tip), blue = out of the surface; stored as
# n * 0.5 + 0.5 in linear 8-bit. Roughness is grey, 0 smooth .. 1 rough (glTF reads green).

def normal_map(height, strength, wrap=True):
    """Normals of a height field (0..1, rows top to bottom): \p strength is the height of 1.0
    in texels. Central differences, wrapping for tiling textures."""
    h = np.asarray(height, np.float64) * strength
    if wrap:
        dx = (np.roll(h, -1, 1) - np.roll(h, 1, 1)) * 0.5
        drow = (np.roll(h, -1, 0) - np.roll(h, 1, 0)) * 0.5
    else:
        drow, dx = np.gradient(h)
    # v runs up the image, rows down: dh/dv = -dh/drow.
    n = np.stack([-dx, drow, np.ones_like(h)], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return n * 0.5 + 0.5


def save_maps(name, height, strength, roughness, wrap=True):
    """Writes <stem>_normal.png (RGB) and <stem>_roughness.png (grey) for texture \p name."""
    stem = name[:-4]
    write_png(os.path.join(HERE, stem + "_normal.png"), to_bytes(normal_map(height, strength, wrap)))
    write_png(os.path.join(HERE, stem + "_roughness.png"), to_bytes(roughness))


def save_bark(name, drawn, strength=6.0):
    """A bark drawn as (rgb, height): the colour and its maps. Bark is rough; the deep cracks
    the roughest."""
    rgb, height = drawn
    save_rgb(name, rgb)
    hn = (height - height.min()) / max(height.max() - height.min(), 1e-9)
    save_maps(name, hn, strength, 0.78 + 0.2 * (1 - hn))


def leaf_height(mask, rgb, relief=None):
    """A leaf's height at the texture's resolution: a blade that swells from its rim (the
    blurred cut-out) plus \p relief (veins pressed in, supersampled like mask), or the colour's
    shading where a drawing has no relief of its own (needles, sprays: their shading is their
    roundness)."""
    m = mask.astype(np.float32)
    h = m.shape[0] // SS
    w = m.shape[1] // SS
    a = m.reshape(h, SS, w, SS).mean(axis=(1, 3))
    dome = a.copy()
    for _ in range(3):
        dome = (dome + np.roll(dome, 1, 0) + np.roll(dome, -1, 0) + np.roll(dome, 1, 1) +
                np.roll(dome, -1, 1)) / 5.0
    dome *= a
    if relief is None:
        lum = (rgb * m[..., None]).mean(axis=-1).reshape(h, SS, w, SS).mean(axis=(1, 3))
        lum = lum / max(lum.max(), 1e-6)
        return 0.6 * dome + 0.4 * lum * a
    r = (relief * m).reshape(h, SS, w, SS).mean(axis=(1, 3))
    return 0.6 * dome + 0.4 * r


def save_leaf_maps(name, mask, rgb, relief=None, roughness=0.55):
    """Normal and roughness maps of a leaf card: a waxy upper side, rougher veins."""
    height = leaf_height(mask, rgb, relief)
    hn = height / max(height.max(), 1e-9)
    save_maps(name, hn, 3.0, np.clip(roughness + 0.25 * (1 - hn), 0, 1), wrap=False)


# ----------------------------------------------------------------------------- barks

def bark_furrowed(seed, dark, light, ridges=6, depth=1.0, warp=0.35, cracks=0.5):
    """Deep vertical furrows whose ridges wander and break into blocks (oak, poplar, willow)."""
    shape = (BARK, BARK)
    u = np.arange(BARK)[None, :] / BARK
    n1 = noise(shape, 40, 120, seed)
    n2 = noise(shape, 10, 40, seed + 1)
    n3 = noise(shape, 3, 3, seed + 2)
    phase = ridges * u + warp * 4 * (n1 - 0.5) + 0.6 * (n2 - 0.5)
    ridge = np.abs(np.sin(math.pi * phase)) ** 0.7
    crack = noise(shape, 12, 4, seed + 3)
    crack = np.clip((crack - (1 - 0.25 * cracks)) * 8, 0, 1)
    shade = 0.25 + depth * 0.6 * ridge + 0.25 * (n3 - 0.5) - 0.5 * crack * ridge
    return colorize(shade, dark, light), shade


def bark_smooth(seed, base, mottle, lenticels=0.0, rings=0.0):
    """Smooth bark with a soft mottling (beech, hedge and shrub stems)."""
    shape = (BARK, BARK)
    m = noise(shape, 30, 30, seed)
    f = noise(shape, 3, 6, seed + 1)
    shade = 0.6 + 0.35 * (m - 0.5) * mottle * 2 + 0.12 * (f - 0.5)
    rgb = colorize(shade, np.asarray(base) * 0.55, np.asarray(base) * 1.15)
    # Smooth bark's relief is its fine grain, raised lenticels and the folds of the rings; the
    # mottling is colour only.
    height = 0.5 + 0.3 * (f - 0.5)
    if lenticels > 0:
        l = noise(shape, 6, 1.2, seed + 2)
        mark = np.clip((l - (1 - 0.2 * lenticels)) * 10, 0, 1)[..., None]
        rgb = rgb * (1 - 0.45 * mark)
        height = height + 0.25 * mark[..., 0]
    if rings > 0:
        v = np.arange(BARK)[:, None] / BARK
        ring = np.abs(np.sin(math.pi * (5 * v + 0.3 * noise(shape, 60, 8, seed + 3))))
        rgb = rgb * (1 - rings * 0.2 * (ring < 0.08)[..., None])
        height = height - 0.3 * rings * np.clip(1 - ring / 0.12, 0, 1)
    return rgb, height


def bark_birch():
    shape = (BARK, BARK)
    base = colorize(0.85 + 0.15 * noise(shape, 20, 20, 11), (0.74, 0.72, 0.68), (0.95, 0.94, 0.91))
    # Horizontal dark lenticels, the birch's signature: three sizes at unrelated spacings, each
    # where a slow mask lets it be, so they come in irregular clusters and gaps (one noise of 14
    # columns drew them evenly spaced, like a ruler's ticks; issue #44).
    mask = noise(shape, 90, 140, 17)
    fine = np.clip((noise(shape, 9, 1.2, 12) - 0.74) * 9, 0, 1) * np.clip((mask - 0.35) * 3, 0, 1)
    mid = np.clip((noise(shape, 20, 2, 18) - 0.76) * 9, 0, 1) * np.clip((0.65 - mask) * 3, 0, 1)
    long_ = np.clip((noise(shape, 45, 3, 19) - 0.8) * 8, 0, 1) * np.clip((noise(shape, 80, 60, 20) - 0.45) * 4, 0, 1)
    lent = np.clip(fine + mid + long_, 0, 1)
    # Black diamond patches and rough dark bands.
    patch = noise(shape, 45, 25, 13)
    patch = np.clip((patch - 0.7) * 6, 0, 1) * (0.7 + 0.3 * noise(shape, 4, 2, 14))
    peel = np.clip((noise(shape, 25, 4, 15) - 0.8) * 6, 0, 1)
    rgb = base * (1 - 0.75 * lent[..., None])
    rgb = rgb * (1 - 0.85 * patch[..., None]) + 0.03 * patch[..., None]
    rgb = rgb * (1 - 0.15 * peel[..., None]) + np.asarray((0.05, 0.02, 0.0)) * peel[..., None]
    # Lenticels are shallow horizontal grooves, the dark patches rough fissured bark, the peel
    # lifted curls.
    height = 0.6 - 0.35 * lent - 0.3 * patch * noise(shape, 3, 1.5, 16) + 0.2 * peel
    return rgb, height


def bark_plates(seed, plate, crack_col, count=60, stretch=(1.0, 2.2), flaky=0.5):
    """Plates split by cracks (Scots pine's flakes, spruce scales)."""
    shape = (BARK, BARK)
    d1, d2, ident = cells(shape, count, seed, stretch)
    edge = np.clip((d2 - d1) / 4.0, 0, 1) ** 0.6
    rng = np.random.default_rng(seed + 5)
    tint = rng.random(count)[ident]
    f = noise(shape, 2, 6, seed + 1)
    shade = (0.55 + 0.35 * tint * flaky + 0.2 * (f - 0.5)) * edge
    rgb = colorize(shade, crack_col, plate)
    # Each plate a little tilted slab (its own height), the cracks between them deep.
    height = edge * (0.7 + 0.3 * tint) + 0.08 * (f - 0.5)
    return rgb, height


def bark_pine(seed):
    """Scots pine (issue #44): grey-brown plates of two sizes split by wavy dark cracks of
    varying width (one colour of even plates read as a diamond lattice), each plate's surface
    split again into thin papery scales with lifted, lighter edges. No orange of its own: the
    preset's bark_color_low/high vertex colours keep it grey-brown low on the stem and turn it
    orange high up, where the same scales read as flaking bark (an orange patch drawn here
    showed everywhere, low too)."""
    shape = (BARK, BARK)
    big1, big2, ident = cells(shape, 34, seed, (1.0, 2.8))
    small1, small2, scale = cells(shape, 140, seed + 7, (1.0, 1.6))
    warp = noise(shape, 6, 10, seed + 1) - 0.5
    width = 5.0 + 5.0 * noise(shape, 40, 60, seed + 2)
    crack = np.clip((big2 - big1 + 3.0 * warp) / width, 0, 1) ** 0.6
    flake_edge = np.clip((small2 - small1) / 2.5, 0, 1)
    rng = np.random.default_rng(seed + 5)
    own = rng.random(34)[ident]
    scale_own = rng.random(140)[scale]
    # Plates a little warmer or greyer, by their own random and a slow noise (no two alike).
    warm = np.clip(0.6 * own + 0.4 * noise(shape, 70, 110, seed + 3), 0, 1)[..., None]
    grey = np.asarray((0.60, 0.54, 0.49), np.float32)
    brown = np.asarray((0.72, 0.56, 0.43), np.float32)
    col = grey * (1 - warm) + brown * warm
    f = noise(shape, 2, 5, seed + 4)
    # A scale's edge is a thin dark line with a lighter lifted lip beside it.
    lip = np.clip(1 - np.abs(flake_edge - 0.35) / 0.2, 0, 1)
    shade = ((0.82 + 0.3 * (own - 0.5) + 0.1 * (scale_own - 0.5) + 0.22 * (f - 0.5)) *
             (0.84 + 0.16 * flake_edge) + 0.06 * lip)
    crack_col = np.asarray((0.12, 0.10, 0.08), np.float32)
    rgb = crack_col + (col * shade[..., None] - crack_col) * crack[..., None]
    height = crack * (0.65 + 0.3 * own) + 0.1 * flake_edge + 0.04 * scale_own + 0.06 * (f - 0.5)
    return np.clip(rgb, 0, 1), height


def bark_palm():
    shape = (BARK, BARK)
    v = np.arange(BARK)[:, None] / BARK
    u = np.arange(BARK)[None, :] / BARK
    wob = noise(shape, 60, 30, 41)
    # Leaf scars: rings every 1/6 of the tile with a ragged edge.
    ring = (6 * v + 0.25 * (wob - 0.5)) % 1.0
    scar = np.clip(1 - np.abs(ring - 0.5) * 5, 0, 1) ** 2
    fibre = noise(shape, 1.5, 14, 42)
    shade = 0.45 + 0.35 * fibre + 0.25 * (1 - scar) - 0.1 * np.sin(2 * math.pi * u * 3) ** 2 * 0
    rgb = colorize(shade * (1 - 0.45 * scar), (0.18, 0.14, 0.10), (0.66, 0.58, 0.46))
    return rgb, shade * (1 - 0.45 * scar)


def bark_stringy(seed, dark, light):
    """Fibrous vertical strips (cypress)."""
    shape = (BARK, BARK)
    s = noise(shape, 2.5, 50, seed)
    w = noise(shape, 20, 80, seed + 1)
    u = np.arange(BARK)[None, :] / BARK
    strip = np.abs(np.sin(math.pi * (14 * u + 2.5 * (w - 0.5)))) ** 0.5
    shade = 0.3 + 0.45 * s + 0.3 * strip
    return colorize(shade, dark, light), shade


# ----------------------------------------------------------------------------- leaves

SS = 3  # supersampling for smooth cut-out edges


def canvas(w, h):
    """Coordinates of a leaf card: x in -1..1 across, t in 0..1 from the stem (bottom row of
    the image) to the tip (top row)."""
    ys, xs = np.mgrid[0:h * SS, 0:w * SS].astype(np.float32)
    x = (xs + 0.5) / (w * SS) * 2 - 1
    t = 1 - (ys + 0.5) / (h * SS)
    return x, t


# While a season's leaf textures are drawn (seasons()): the colour change applied to a leaf's
# supersampled colour before it is written, and no maps (a season's leaf shares the summer
# leaf's normal and roughness maps).
SEASON_RECOLOR = None


def finish_leaf(name, w, h, mask, rgb, relief=None, roughness=0.55):
    """Downsamples the supersampled mask and colour, bleeds the colour under the transparent
    texels (no dark fringe when mipmapped) and writes the RGBA PNG, and its normal and
    roughness maps (\p relief: the blade's own height, supersampled; see leaf_height)."""
    if SEASON_RECOLOR is not None:
        rgb = SEASON_RECOLOR(rgb, mask)
    else:
        save_leaf_maps(name, mask, rgb, relief, roughness)
    mask = mask.astype(np.float32)
    a = mask.reshape(h, SS, w, SS).mean(axis=(1, 3))
    c = (rgb * mask[..., None]).reshape(h, SS, w, SS, 3).sum(axis=(1, 3))
    wsum = mask.reshape(h, SS, w, SS).sum(axis=(1, 3))[..., None]
    mean = c.sum(axis=(0, 1)) / max(wsum.sum(), 1)
    col = np.where(wsum > 0, c / np.maximum(wsum, 1e-6), mean)
    # Bleed: a few passes of averaging covered neighbours into uncovered texels.
    filled = wsum[..., 0] > 0
    for _ in range(6):
        acc = np.zeros_like(col)
        cnt = np.zeros(filled.shape, np.float32)
        for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
            sh = np.roll(np.roll(col, dy, 0), dx, 1)
            sf = np.roll(np.roll(filled, dy, 0), dx, 1)
            acc += sh * sf[..., None]
            cnt += sf
        grow = (~filled) & (cnt > 0)
        col[grow] = acc[grow] / cnt[grow][:, None]
        filled = filled | grow
    col[~filled] = mean
    rgba = np.concatenate([col, a[..., None]], axis=-1)
    write_png(os.path.join(HERE, name), to_bytes(rgba))
    return rgba


def blade_shading(x, t, width, base, seed, veins=8, vein_angle=0.6, midrib=0.03, gloss=0.1):
    """Colour of a simple blade: midrib, side veins, darker rim, noise."""
    h, w = x.shape
    n = noise((h // SS, w // SS), 6, 6, seed)
    n = np.kron(n, np.ones((SS, SS)))
    rel = np.abs(x) / np.maximum(width, 1e-3)
    shade = 0.85 + 0.25 * (n - 0.5) + gloss * (1 - rel)
    shade *= 0.8 + 0.2 * np.clip((1 - rel) / 0.15, 0, 1)
    rgb = np.asarray(base) * shade[..., None]
    vein = np.abs(x) < midrib
    phase = (t - vein_angle * np.abs(x)) * veins
    side = (np.abs(phase - np.round(phase)) < 0.05) & (rel < 0.9)
    light = np.asarray(base) * 1.35 + 0.05
    rgb = np.where((vein | side)[..., None], 0.55 * rgb + 0.45 * light, rgb)
    return rgb


def blade_relief(x, t, width, veins=8, vein_angle=0.6, midrib=0.03, gloss=0.1):
    """The height of a simple blade (blade_shading's veins, same arguments): arched across,
    falling to the rim, the midrib and side veins pressed in as on a leaf's upper side."""
    rel = np.abs(x) / np.maximum(width, 1e-3)
    height = 1.0 - 0.35 * np.clip(rel, 0, 1) ** 2
    vein = np.abs(x) < midrib * 1.6
    phase = (t - vein_angle * np.abs(x)) * veins
    d = np.abs(phase - np.round(phase))
    side = np.clip(1 - d / 0.08, 0, 1) * (rel < 0.9)
    return height - 0.45 * vein - 0.3 * side


def simple_leaf(name, w, h, width_fn, base, seed, stem=0.08, **shading):
    x, t = canvas(w, h)
    k = np.clip((t - stem) / (1 - stem), 0, 1)
    width = width_fn(k, x)
    mask = ((np.abs(x) < width) & (t > stem)) | ((t <= stem + 0.01) & (np.abs(x) < 0.05))
    rgb = blade_shading(x, k, width, base, seed, **shading)
    return finish_leaf(name, w, h, mask, rgb, relief=blade_relief(x, k, width, **shading),
                       roughness=0.6 - shading.get("gloss", 0.1))


def oak_width(k, x):
    outline = 0.95 * np.sin(math.pi * np.clip(k, 0, 1) ** 1.25) ** 0.7
    lobes = 0.55 + 0.45 * np.abs(np.cos(math.pi * 4.5 * k)) ** 0.6
    return outline * lobes


def birch_width(k, x):
    outline = 0.95 * np.sin(math.pi * np.clip(k, 0, 1) ** 0.7) ** 0.9 * (1 - 0.3 * k)
    teeth = 1 - 0.07 * np.abs(np.sin(math.pi * 22 * k))
    return outline * teeth


def beech_width(k, x):
    outline = 0.9 * np.sin(math.pi * np.clip(k, 0, 1) ** 0.9) ** 0.8
    return outline * (1 - 0.04 * np.abs(np.sin(math.pi * 8 * k)))


def willow_width(k, x):
    return 0.9 * np.sin(math.pi * np.clip(k, 0, 1) ** 0.9) ** 1.3 * (1 - 0.03 * np.abs(np.sin(math.pi * 30 * k)))


def poplar_width(k, x):
    # Rhombic: widest at a third, straight flanks to a pointed tip.
    wide = np.where(k < 0.3, np.sin(0.5 * math.pi * np.clip(k, 0, 0.3) / 0.3) ** 0.8, (1 - k) / 0.7)
    return 0.95 * wide * (1 - 0.05 * np.abs(np.sin(math.pi * 16 * k)))


def maple_leaf(name, w, h, base, seed):
    x, t = canvas(w, h)
    cx, cy = 0.0, 0.42
    px, py = x, (t - cy) * 2.0  # the card is twice as tall as wide → square leaf space
    r = np.hypot(px, py)
    theta = np.arctan2(px, py)  # 0 = up
    mask = np.zeros(x.shape, bool)
    for ang, length, width in ((0, 1.0, 0.26), (-60, 0.95, 0.25), (60, 0.95, 0.25),
                               (-120, 0.6, 0.22), (120, 0.6, 0.22)):
        a = math.radians(ang)
        dx, dy = math.sin(a), math.cos(a)
        along = px * dx + py * dy
        across = px * dy - py * dx
        s = np.clip(along / length, 0, 1)
        half = width * np.clip(np.sin(math.pi * np.clip(s, 0, 1) ** 0.6), 0, 1) ** 0.9
        # A pair of side teeth on each lobe.
        half = half * (1 + 0.6 * np.exp(-((s - 0.6) / 0.07) ** 2))
        mask |= (along > 0) & (along < length) & (np.abs(across) < half)
    mask |= r < 0.28
    stem = (np.abs(x) < 0.035) & (t < cy) & (t > 0.0)
    mask |= stem
    # Palmate veins: lines from the centre towards each lobe tip.
    rgb = np.asarray(base) * (0.85 + 0.15 * np.kron(noise((h, w), 6, 6, seed), np.ones((SS, SS))))[..., None]
    vein = np.zeros(x.shape, bool)
    for ang in (0, -60, 60, -120, 120):
        a = math.radians(ang)
        across = px * math.cos(a) - py * math.sin(a)
        along = px * math.sin(a) + py * math.cos(a)
        vein |= (np.abs(across) < 0.025) & (along > 0)
    rgb = np.where(vein[..., None], rgb * 0.6 + 0.4 * (np.asarray(base) * 1.4 + 0.05), rgb)
    rgb = rgb * (0.8 + 0.2 * np.clip(1 - r / 1.1, 0, 1))[..., None] + 0.05
    return finish_leaf(name, w, h, mask, rgb,
                       relief=1.0 - 0.5 * vein - 0.2 * np.clip(r / 1.1, 0, 1))


def strokes(x, t, segs, aspect):
    """Mask of line segments [(x0, t0, x1, t1, half_width)] in card space (aspect = w/h)."""
    mask = np.zeros(x.shape, bool)
    X = x * aspect  # make distances isotropic: x spans 2*aspect, t spans 1 → scale
    for (x0, t0, x1, t1, hw) in segs:
        ax, ay = x0 * aspect, t0
        bx, by = x1 * aspect, t1
        vx, vy = bx - ax, by - ay
        ll = vx * vx + vy * vy
        lo_x, hi_x = min(ax, bx) - hw, max(ax, bx) + hw
        lo_y, hi_y = min(ay, by) - hw, max(ay, by) + hw
        sel = (X >= lo_x) & (X <= hi_x) & (t >= lo_y) & (t <= hi_y)
        if not sel.any():
            continue
        px, py = X[sel] - ax, t[sel] - ay
        s = np.clip((px * vx + py * vy) / max(ll, 1e-12), 0, 1)
        d = np.hypot(px - s * vx, py - s * vy)
        mask[sel] |= d < hw
    return mask


def needle_tuft(name, w, h, base, seed, count=220, spread=55, length=(0.75, 0.98)):
    """Scots pine: needles in a brush from the shoot at the bottom."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = w / h * 0.5 * 2  # x spans 2 units across w, t spans 1 over h
    aspect = (w / h) / 2.0
    segs = [(0.0, 0.0, 0.0, 0.35, 0.02)]
    for _ in range(count):
        base_t = rng.uniform(0.05, 0.45)
        ang = math.radians(rng.uniform(-spread, spread))
        L = rng.uniform(*length) * (1 - base_t * 0.6)
        x1 = math.sin(ang) * L * 0.8 / aspect
        segs.append((0.0, base_t, np.clip(x1, -0.97, 0.97), min(0.99, base_t + math.cos(ang) * L * 0.75), 0.0045))
    mask = strokes(x, t, segs, aspect)
    shade = 0.8 + 0.3 * np.kron(noise((h, w), 2, 8, seed), np.ones((SS, SS)))
    rgb = np.asarray(base) * shade[..., None] * (0.75 + 0.35 * t)[..., None]
    return finish_leaf(name, w, h, mask, rgb)


def pine_shoot(name, w, h, base, seed, fascicles=46, twig=(0.45, 0.30, 0.18)):
    """Scots pine (issue #33): a shoot seen from the side with its needles in pairs, long (a
    third to a half of the card), thin and stiff, each pair turned forward at its own angle and
    shaded on its own, so the card reads as a brush of needles with light between them, not as
    one broad leaf. Shoot up the middle from the stem (bottom edge) to near the top."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    mask = strokes(x, t, [(0.0, 0.0, 0.0, 0.86, 0.016)], aspect)
    rgb = np.zeros(x.shape + (3,), np.float32) + np.asarray(twig, np.float32)
    base = np.asarray(base, np.float32)
    for i in range(fascicles):
        s = 0.06 + 0.80 * (i + rng.uniform(0, 1)) / fascicles
        for side in (-1, 1):
            ang = math.radians(rng.uniform(22, 62)) * side * (1 if rng.random() < 0.85 else -1)
            L = rng.uniform(0.36, 0.52) * (1 - 0.35 * max(0.0, s - 0.55))
            bend = rng.uniform(-0.06, 0.06)
            mx = math.sin(ang) * L * 0.5 / aspect
            mt = s + math.cos(ang) * L * 0.5
            ex = math.sin(ang + bend) * L / aspect
            et = s + math.cos(ang + bend) * L * 0.97
            ex = float(np.clip(ex, -0.98, 0.98))
            et = min(0.995, et)
            needle = strokes(x, t, [(0.0, s, mx, mt, 0.0055), (mx, mt, ex, et, 0.0045)], aspect)
            tone = rng.uniform(0.7, 1.15)
            # Lighter toward the tip, darker inside the brush.
            col = base * tone * (0.75 + 0.45 * np.clip((t - s) / max(L, 1e-3), 0, 1))[..., None]
            rgb = np.where(needle[..., None], col, rgb)
            mask = mask | needle
    return finish_leaf(name, w, h, mask, np.clip(rgb, 0, 1))


def sprig(name, w, h, base, seed, needle=0.11, density=90, angle=55, twig=(0.26, 0.22, 0.12)):
    """Spruce: a shoot with short stiff needles all round it (a bottlebrush seen from the side:
    each needle at its own angle and foreshortened, not a flat comb of mirrored pairs, which
    read as a lobed leaf; issue #44) on a thin twig, and side shoots."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    axes = [(0.0, 0.0, 0.0, 0.98, 1.0)]
    for k in range(3):
        t0 = 0.25 + 0.22 * k
        for side in (-1, 1):
            L = 0.45 - 0.1 * k
            a = math.radians(48)
            axes.append((0.0, t0, side * math.sin(a) * L / aspect * 0.5, t0 + math.cos(a) * L, 0.7))
    twigs, needles = [], []
    for (x0, t0, x1, t1, scale) in axes:
        twigs.append((x0, t0, x1, t1, 0.006))
        dx, dt = (x1 - x0) * aspect * 2, t1 - t0
        L = math.hypot(dx, dt)
        ux, ut = dx / L, dt / L
        n = int(1.5 * density * L)
        for i in range(n):
            s = (i + rng.random()) / n
            px, pt = x0 * aspect * 2 + dx * s, t0 + dt * s
            for side in (-1, 1):
                a = math.radians(rng.uniform(angle - 30, angle + 40)) * side
                vx = ux * math.cos(a) - ut * math.sin(a)
                vt = ux * math.sin(a) + ut * math.cos(a)
                # foreshortened: needles pointing toward or away from the viewer look shorter
                nl = needle * scale * (1 - 0.4 * s) * rng.uniform(0.8, 1.1) * rng.uniform(0.35, 1.0)
                needles.append((px / (aspect * 2), pt, (px + vx * nl) / (aspect * 2), pt + vt * nl, 0.008))
    mt = strokes(x, t, twigs, aspect)
    mn = strokes(x, t, needles, aspect)
    shade = 0.8 + 0.35 * np.kron(noise((h, w), 3, 3, seed), np.ones((SS, SS)))
    rgb = np.asarray(base) * shade[..., None] * (0.8 + 0.3 * t)[..., None]
    rgb = np.where(mt[..., None], np.asarray(twig), rgb)
    return finish_leaf(name, w, h, mt | mn, rgb)


def frond(name, w, h, base, seed):
    """Palm frond: a curved rachis with long leaflets drooping to both sides."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    segs = [(0.0, 0.0, 0.0, 1.0, 0.012)]
    leaflets = []
    n = 46
    for i in range(n):
        s = 0.08 + 0.9 * i / n
        L = 0.42 * math.sin(math.pi * min(1.0, (s - 0.05) / 0.95)) ** 0.6 + 0.05
        for side in (-1, 1):
            a = math.radians(rng.uniform(38, 52))
            x1 = side * math.sin(a) * L / aspect * 0.5
            t1 = s + math.cos(a) * L * 0.9 - 0.05
            xm, tm = x1 * 0.55, s + (t1 - s) * 0.65
            leaflets.append((0.0, s, xm, tm, 0.011))
            leaflets.append((xm, tm, x1, t1, 0.008))
    mr = strokes(x, t, segs, aspect)
    ml = strokes(x, t, leaflets, aspect)
    shade = 0.8 + 0.3 * np.kron(noise((h, w), 2, 10, seed), np.ones((SS, SS)))
    rgb = np.asarray(base) * shade[..., None] * (0.75 + 0.4 * np.abs(x))[..., None]
    rgb = np.where(mr[..., None], np.asarray((0.55, 0.55, 0.30)), rgb)
    return finish_leaf(name, w, h, mr | ml, rgb)


def scale_spray(name, w, h, base, seed):
    """Cypress: a dense flattened spray of scale-leaf shoots, forking as it goes."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    segs = []

    def branch(x0, t0, ang, L, width, depth):
        x1 = float(np.clip(x0 + math.sin(ang) * L / aspect, -0.97, 0.97))
        t1 = float(np.clip(t0 + math.cos(ang) * L, 0.0, 0.99))
        segs.append((x0, t0, x1, t1, width))
        if depth == 0:
            return
        side = 1 if rng.random() < 0.5 else -1
        for f in (0.2, 0.38, 0.56, 0.74, 0.9):
            xs, ts = x0 + (x1 - x0) * f, t0 + (t1 - t0) * f
            side = -side
            branch(xs, ts, ang + side * math.radians(rng.uniform(35, 50)), L * 0.42 * (1.1 - 0.5 * f),
                   width * 0.75, depth - 1)

    branch(0.0, 0.0, 0.0, 0.97, 0.016, 3)
    mask = strokes(x, t, segs, aspect)
    shade = 0.75 + 0.4 * np.kron(noise((h, w), 1.5, 1.5, seed), np.ones((SS, SS)))
    rgb = np.asarray(base) * shade[..., None] * (0.8 + 0.3 * t)[..., None]
    return finish_leaf(name, w, h, mask, rgb)


def ellipse_leaf_mask(x, t, aspect, cx, ct, ang, L, W):
    """An elliptic leaf from (cx, ct) pointing at angle ang (radians from up), length L."""
    X = (x - cx) * aspect
    T = t - ct
    along = X * math.sin(ang) + T * math.cos(ang)
    across = X * math.cos(ang) - T * math.sin(ang)
    s = along / L
    half = W * np.clip(np.sin(math.pi * np.clip(s, 0, 1)), 0, 1) ** 0.8
    return (s > 0) & (s < 1) & (np.abs(across) < half), along, across


def rhododendron(name, w, h, leaf_col, flower_col, seed):
    """Flowering shrub: a whorl of leathery leaves under a rounded truss of pink flowers."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    mask = np.zeros(x.shape, bool)
    rgb = np.zeros(x.shape + (3,), np.float32)
    for ang in (-75, -45, -18, 18, 45, 75):
        m, along, across = ellipse_leaf_mask(x, t, aspect, 0.0, 0.1, math.radians(ang), 0.6, 0.09)
        vein = np.abs(across) < 0.008
        col = np.asarray(leaf_col) * (0.85 + 0.2 * (along / 0.55))[..., None]
        col = np.where(vein[..., None], col * 1.3 + 0.05, col)
        rgb = np.where(m[..., None], col, rgb)
        mask |= m
    # Flower truss: a dome of five-petalled flowers.
    for i in range(26):
        fx = rng.uniform(-0.6, 0.6)
        ft = 0.6 + rng.uniform(-0.15, 0.3) * (1 - abs(fx))
        X = (x - fx) * aspect
        T = t - ft
        r = np.hypot(X, T)
        th = np.arctan2(X, T) + rng.uniform(0, 6.28)
        petal = 0.075 * (0.75 + 0.25 * np.abs(np.cos(2.5 * th)))
        m = r < petal
        col = np.asarray(flower_col) * (0.75 + 0.35 * np.clip(r / petal, 0, 1))[..., None]
        col = np.where((r < 0.018)[..., None], np.asarray((0.95, 0.85, 0.45)), col)
        rgb = np.where(m[..., None], col, rgb)
        mask |= m
    stem = strokes(x, t, [(0.0, 0.0, 0.0, 0.15, 0.015)], aspect)
    rgb = np.where((stem & ~mask)[..., None], np.asarray((0.35, 0.28, 0.2)), rgb)
    return finish_leaf(name, w, h, mask | stem, rgb)


def privet(name, w, h, base, seed):
    """Hedge (privet): a shoot with pairs of small opposite oval leaves, densely set."""
    rng = np.random.default_rng(seed)
    x, t = canvas(w, h)
    aspect = (w / h) / 2.0
    mask = strokes(x, t, [(0.0, 0.0, 0.0, 0.9, 0.012)], aspect)
    rgb = np.zeros(x.shape + (3,), np.float32) + np.asarray((0.35, 0.3, 0.2))
    for k in range(6):
        ct = 0.08 + 0.145 * k
        for side in (-1, 1):
            ang = side * math.radians(rng.uniform(40, 70)) * (1 - 0.05 * k)
            L = 0.3 * (1 - 0.06 * k)
            m, along, across = ellipse_leaf_mask(x, t, aspect, 0.0, ct, ang, L, 0.06 * (1 - 0.05 * k))
            shade = 0.8 + 0.3 * rng.random() + 0.15 * (along / L)
            col = np.asarray(base) * shade[..., None]
            col = np.where((np.abs(across) < 0.006)[..., None], col * 1.35 + 0.04, col)
            rgb = np.where(m[..., None], col, rgb)
            mask |= m
    m, along, across = ellipse_leaf_mask(x, t, aspect, 0.0, 0.86, 0.0, 0.14, 0.035)
    rgb = np.where(m[..., None], np.asarray(base) * 1.25, rgb)
    mask |= m
    return finish_leaf(name, w, h, mask, rgb)


# ----------------------------------------------------------------------------- the defaults
# The bark and leaf of species without textures of their own (the demo's alders among them).
# Drawn texel by texel with Python's own random stream: this is the drawing the demo's exports
# were made with, kept as it is so they stay byte-identical.

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


def default_bark(path, size=256):
    rng = random.Random(42)
    n1 = periodic_noise(rng, 8, 4)
    n2 = periodic_noise(rng, 32, 16)
    n3 = periodic_noise(rng, 64, 64)
    rows = []
    heights = []  # the shade is the bark's height: ridges light, cracks dark
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
            heights.append(shade)
            r = int(255 * min(1.0, 0.42 * shade + 0.04))
            g = int(255 * min(1.0, 0.31 * shade + 0.03))
            b = int(255 * min(1.0, 0.22 * shade + 0.02))
            row += [r, g, b]
        rows.append(row)
    write_png(path, np.array(rows, np.uint8).reshape(size, size, 3))
    height = np.array(heights).reshape(size, size)
    hn = (height - height.min()) / max(height.max() - height.min(), 1e-9)
    write_png(path[:-4] + "_normal.png", to_bytes(normal_map(hn, 6.0)))
    write_png(path[:-4] + "_roughness.png", to_bytes(0.78 + 0.2 * (1 - hn)))


def default_leaf(path, width=256, height=512):
    rng = random.Random(7)
    n = periodic_noise(rng, 16, 32)
    rows = []
    covered, relief = [], []  # for the maps: the cut-out and the veins pressed in
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
                covered.append(False)
                relief.append(0.0)
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
            covered.append(True)
            relief.append(1.0 - 0.35 * min(1.0, abs(s) / max(blade, 1e-3)) ** 2 - 0.45 * vein)
        rows.append(row)
    write_png(path, np.array(rows, np.uint8).reshape(height, width, 4))
    up = np.ones((SS, SS))
    mask = np.kron(np.array(covered, np.float32).reshape(height, width), up) > 0.5
    hmap = leaf_height(mask, None, np.kron(np.array(relief).reshape(height, width), up))
    hn = hmap / max(hmap.max(), 1e-9)
    write_png(path[:-4] + "_normal.png", to_bytes(normal_map(hn, 3.0, wrap=False)))
    write_png(path[:-4] + "_roughness.png", to_bytes(np.clip(0.55 + 0.25 * (1 - hn), 0, 1)))


# ----------------------------------------------------------------------------- leaf clusters

def paste_leaf(rgb, alpha, leaf, ax, ay, dx, dy, length, width, shade):
    """Draws the leaf image (RGBA, stem at the bottom row) into a supersampled tile: stem at
    (ax, ay), pointing along the unit (dx, dy), length and width in tile pixels; over what is
    there (later leaves in front)."""
    H, W = alpha.shape
    lh, lw = leaf.shape[:2]
    qx, qy = dy, -dx  # across, to the right of the heading
    ends = [(ax, ay), (ax + dx * length, ay + dy * length)]
    xs = [e[0] + sgn * qx * width / 2 for e in ends for sgn in (-1, 1)]
    ys = [e[1] + sgn * qy * width / 2 for e in ends for sgn in (-1, 1)]
    x0, x1 = max(0, int(min(xs)) - 1), min(W, int(max(xs)) + 2)
    y0, y1 = max(0, int(min(ys)) - 1), min(H, int(max(ys)) + 2)
    if x0 >= x1 or y0 >= y1:
        return
    yy, xx = np.mgrid[y0:y1, x0:x1].astype(np.float32) + 0.5
    px, py = xx - ax, yy - ay
    t = (px * dx + py * dy) / length
    u = (px * qx + py * qy) / (width / 2)
    inside = (t >= 0) & (t < 1) & (np.abs(u) < 1)
    col = np.clip(((u + 1) / 2 * lw).astype(int), 0, lw - 1)
    row = np.clip(((1 - t) * lh).astype(int), 0, lh - 1)
    sample = leaf[row, col]
    a = np.where(inside, sample[..., 3], 0.0)
    region = rgb[y0:y1, x0:x1]
    region[:] = region * (1 - a[..., None]) + sample[..., :3] * shade * a[..., None]
    alpha[y0:y1, x0:x1] = alpha[y0:y1, x0:x1] * (1 - a) + a


# The cluster atlas layout (engine/mesh/leafclusters.h): 4 x 2 tiles numbered from the bottom
# left along rows; tiles 0-6 are sprays, tile 7 the single leaf.
ATLAS_COLS, ATLAS_ROWS = 4, 2
SPRAYS = ATLAS_COLS * ATLAS_ROWS - 1


def tile_offset(k, tile):
    """Pixel offset (x, y) of atlas tile k in the image (rows run downward; tile 0 bottom left)."""
    return (k % ATLAS_COLS) * tile, (ATLAS_ROWS - 1 - k // ATLAS_COLS) * tile


def spray_tiles(leaves, aspect, seed, count, scale, twig, tile, colours=None):
    """The seven spray tiles of a cluster atlas (see cluster_atlas), leaves scale x as many and
    sqrt(scale) x as long as at scale 1. \p leaves: the leaf drawings a spray picks from (one,
    or a season's palette); \p colours: how a tile picks them, (seed, weights) -- each tile has
    a dominant drawing and about a third of its leaves take another, so that cards differ from
    each other and a spray mixes leaves at different stages. The shapes depend on \p seed only,
    never on \p leaves or \p colours (a season's atlas shares the summer atlas's alpha and maps).
    Each spray is drawn differently: its own leaf count, twig bend and length, spread of the
    leaf angles and leaf length."""
    rng = np.random.default_rng(seed)
    crng = np.random.default_rng(colours[0] if colours else 0)
    weights = np.asarray(colours[1] if colours else [1.0] * len(leaves), np.float64)
    weights = weights / weights.sum()
    rgb = np.zeros((tile * ATLAS_ROWS, tile * ATLAS_COLS, 3), np.float32)
    alpha = np.zeros((tile * ATLAS_ROWS, tile * ATLAS_COLS), np.float32)
    grow = math.sqrt(scale)
    for k in range(SPRAYS):
        ox, oy = tile_offset(k, tile)
        dominant = int(crng.choice(len(leaves), p=weights))
        leaves_n = int(round(rng.integers(count[0], count[1] + 1) * scale))
        bend = rng.uniform(-0.2, 0.2)
        reach = rng.uniform(0.70, 0.84)  # how far up the tile the twig goes
        angles = (rng.uniform(20, 40), rng.uniform(65, 90))  # leaf angles off the twig, degrees
        size = rng.uniform(0.9, 1.1)
        # Twig: from the middle of the bottom edge up, bending to one side.
        pts = [(0.5 + bend * s * s, 0.02 + reach * s) for s in np.linspace(0, 1, 12)]
        order = []
        for i in range(leaves_n):
            s = 0.08 + 0.86 * i / max(leaves_n - 1, 1)
            side = -1 if i % 2 else 1
            if i == leaves_n - 1:
                side = 0
            order.append((s, side))
        # Far leaves first (darker), near ones over them.
        depth = rng.permutation(len(order))
        pick = [dominant if crng.random() < 0.65 else int(crng.choice(len(leaves), p=weights))
                for _ in order]
        for j in np.argsort(depth):
            s, side = order[j]
            cx, cy = 0.5 + bend * s * s, 0.02 + reach * s
            tang = np.array([2 * bend * s, reach])
            tang /= np.linalg.norm(tang)
            ang = 0.0 if side == 0 else side * math.radians(rng.uniform(*angles))
            dx = tang[0] * math.cos(ang) - tang[1] * math.sin(ang)
            dy = tang[0] * math.sin(ang) + tang[1] * math.cos(ang)
            length = min(0.62, rng.uniform(0.40, 0.50) * grow * size) * (1 - 0.25 * s) * (0.8 if side == 0 else 1.0)
            turn = rng.uniform(0.7, 1.0)  # foreshortening: a leaf turned in depth
            shade = 0.7 + 0.4 * depth[j] / max(len(order) - 1, 1)
            # A leaf cut by the tile's edge would show the card's straight edge: shortened until
            # its tip and its widest part stay inside the tile.
            for _ in range(20):
                half = 0.5 * length * aspect * turn
                ok = True
                for f, w in ((1.0, 0.0), (0.5, half), (0.5, -half)):
                    px = cx + dx * length * f + dy * w
                    py = cy + dy * length * f - dx * w
                    ok = ok and 0.01 <= px <= 0.99 and 0.01 <= py <= 0.99
                if ok:
                    break
                length *= 0.9
            # Tile space (y up) to image rows (y down).
            paste_leaf(rgb[oy:oy + tile, ox:ox + tile], alpha[oy:oy + tile, ox:ox + tile],
                       leaves[pick[j]], cx * tile, (1 - cy) * tile, dx, -dy, length * tile,
                       length * aspect * turn * tile, shade)
        twig_mask = np.zeros((tile, tile), np.float32)
        yy, xx = np.mgrid[0:tile, 0:tile].astype(np.float32) + 0.5
        for (a0, b0), (a1, b1) in zip(pts[:-1], pts[1:]):
            ax, ay, bx, by = a0 * tile, (1 - b0) * tile, a1 * tile, (1 - b1) * tile
            vx, vy = bx - ax, by - ay
            ss = np.clip(((xx - ax) * vx + (yy - ay) * vy) / (vx * vx + vy * vy), 0, 1)
            d = np.hypot(xx - ax - ss * vx, yy - ay - ss * vy)
            twig_mask = np.maximum(twig_mask, (d < 0.010 * tile * (1.2 - 0.6 * b0)).astype(np.float32))
        # The twig behind the near leaves: only where the leaves leave it visible.
        sub_rgb, sub_a = rgb[oy:oy + tile, ox:ox + tile], alpha[oy:oy + tile, ox:ox + tile]
        show = twig_mask * (1 - sub_a)
        sub_rgb[:] = sub_rgb + np.asarray(twig, np.float32) * show[..., None]
        sub_a[:] = sub_a + show
    return rgb, alpha


def single_leaf_tile(rgb, alpha, leaf, tile):
    """Tile 7 of an atlas: the single leaf stretched to the tile."""
    ox, oy = tile_offset(SPRAYS, tile)
    lh, lw = leaf.shape[:2]
    yy, xx = np.mgrid[0:tile, 0:tile]
    sample = leaf[(yy * lh) // tile, (xx * lw) // tile]
    rgb[oy:oy + tile, ox:ox + tile] = sample[..., :3] * sample[..., 3:4]
    alpha[oy:oy + tile, ox:ox + tile] = sample[..., 3]


def sprays_alpha(alpha, tile):
    """Mean alpha of the spray tiles."""
    return float(np.mean([alpha[oy:oy + tile, ox:ox + tile].mean()
                          for ox, oy in (tile_offset(k, tile) for k in range(SPRAYS))]))


def write_atlas(name, rgb, alpha, size):
    col = rgb / np.maximum(alpha, 1e-6)[..., None]
    return finish_leaf(name, size * ATLAS_COLS // ATLAS_ROWS, size, alpha, np.clip(col, 0, 1))


def cluster_atlas(name, leaf, aspect, seed, count=(6, 9), twig=(0.30, 0.24, 0.17), size=512,
                  palette=None):
    """A species' leaf cluster atlas (engine/mesh/leafclusters.h): 4 x 2 tiles, seven sprays
    of the species' leaf on a twig from the bottom edge of the tile (alternate sides, each leaf
    at its own angle, foreshortened and shaded as if turned in depth; each spray its own
    count, bend and spread) and the single leaf stretched to the eighth tile. \p aspect is
    the leaf card's width / length. A cluster card covers what its leaves' cards cover, so a
    spray must be about as opaque as the single leaf's card: the sprays get more and longer
    leaves until their tiles are (nearly) as covered as the leaf. \p palette: (leaf drawings,
    weights, colour seed) the sprays' leaves are picked from (autumn), else the leaf alone.
    The image is size x 2 size pixels."""
    tile = size * SS // ATLAS_ROWS
    target = float(leaf[..., 3].mean())
    leaves, colours = ([leaf], None) if palette is None else (palette[0], (palette[2], palette[1]))
    for scale in (1.0, 1.4, 1.9, 2.5, 3.2, 4.0, 5.0):
        rgb, alpha = spray_tiles(leaves, aspect, seed, count, scale, twig, tile, colours)
        if sprays_alpha(alpha, tile) >= 0.9 * target:
            break
    single_leaf_tile(rgb, alpha, leaf, tile)
    return write_atlas(name, rgb, alpha, size)


def draw_needles(rgb, alpha, segs):
    """Draws line segments into a supersampled tile (y down): [(x0, y0, x1, y1, half_width,
    colour at the start, colour at the end)] in pixels, later ones over earlier ones."""
    H, W = alpha.shape
    for (x0, y0, x1, y1, hw, c0, c1) in segs:
        lo_x, hi_x = max(0, int(min(x0, x1) - hw - 1)), min(W, int(max(x0, x1) + hw + 2))
        lo_y, hi_y = max(0, int(min(y0, y1) - hw - 1)), min(H, int(max(y0, y1) + hw + 2))
        if lo_x >= hi_x or lo_y >= hi_y:
            continue
        yy, xx = np.mgrid[lo_y:hi_y, lo_x:hi_x].astype(np.float32) + 0.5
        vx, vy = x1 - x0, y1 - y0
        ll = max(vx * vx + vy * vy, 1e-9)
        s = np.clip(((xx - x0) * vx + (yy - y0) * vy) / ll, 0, 1)
        inside = np.hypot(xx - x0 - s * vx, yy - y0 - s * vy) < hw
        if not inside.any():
            continue
        col = np.asarray(c0, np.float32) * (1 - s[..., None]) + np.asarray(c1, np.float32) * s[..., None]
        region = rgb[lo_y:hi_y, lo_x:hi_x]
        region[inside] = col[inside]
        alpha[lo_y:hi_y, lo_x:hi_x][inside] = 1.0


def needle_sprays(kind, seed, base, twig, tile, scale):
    """The seven spray tiles of a conifer's needle-cluster atlas (issue #33), drawn needle by
    needle at the atlas's resolution (a pasted shoot image would shrink its needles below a
    texel). kind "pine": a short twig forking into four or five shoots, each ending in a
    shaving brush of long needles (a sixth of the tile, thin) round its last half, denser
    toward the tip, each needle at its own angle (mirrored pairs drew a fern's herringbone),
    lighter at the tips, with sky between the brushes, so that a card reads as a pine's tufts,
    not as a broad leaf. kind "spruce": a flat branchlet (an axis with
    four to six alternate side shoots) densely set with short stiff needles on both sides, the
    side shoots apart, lighter at the new growth. \p scale: needles per shoot, raised until the
    tiles are about as opaque as the shoot card (at most 2.2x)."""
    rng = np.random.default_rng(seed)
    rgb = np.zeros((tile * ATLAS_ROWS, tile * ATLAS_COLS, 3), np.float32)
    alpha = np.zeros((tile * ATLAS_ROWS, tile * ATLAS_COLS), np.float32)
    base = np.asarray(base, np.float32)
    twig = np.asarray(twig, np.float32)
    T = float(tile)

    def P(x, y):  # tile space (y up, 0..1) to pixels (y down)
        return x * T, (1 - y) * T

    for k in range(SPRAYS):
        ox, oy = tile_offset(k, tile)
        segs_twig, segs = [], []
        bend = rng.uniform(-0.15, 0.15)
        if kind == "pine":
            # Two or three shoots from a short fork, each the last years' growth of a pine
            # branch: a bare base, then paired needles (fascicles) 0.2-0.3 of the tile long,
            # pointing forward at 15-60 degrees on both sides and crossing the shoot, each pair
            # a little apart and bent (twisted needles), thick enough (about 3 texels of the
            # 256 tile at the base, tapering) to survive two mip levels, darker at the base and
            # lighter at the tips; sky between the shoots, so that from a few metres a card
            # reads as spiky tufts at the branch ends, not as a frond (issue #33).
            fork = rng.uniform(0.05, 0.10)
            stem_top = (0.5 + bend * 0.2, fork)
            segs_twig.append((0.5, 0.0, stem_top[0], stem_top[1], 0.012))
            shoots = int(rng.integers(2, 4))
            spread = rng.uniform(50, 70)
            for i in range(shoots):
                a = math.radians(-spread + 2 * spread * (i + rng.uniform(0.3, 0.7)) / shoots)
                L = rng.uniform(0.36, 0.46) * (1.0 - 0.25 * abs(math.sin(a)))
                x0, y0 = stem_top
                x1 = float(np.clip(x0 + math.sin(a) * L, 0.22, 0.78))
                y1 = min(0.70, y0 + math.cos(a) * L)
                segs_twig.append((x0, y0, x1, y1, 0.008))
                ux, uy = x1 - x0, y1 - y0
                ln = math.hypot(ux, uy)
                ux, uy = ux / ln, uy / ln
                pairs = int(24 * scale)
                for j in range(pairs):
                    u = (j + rng.random()) / pairs
                    s = 0.22 + 0.78 * math.sqrt(u)  # denser toward the tip
                    px, py = x0 + (x1 - x0) * s, y0 + (y1 - y0) * s
                    side = -1 if rng.random() < 0.5 else 1
                    ang0 = side * rng.uniform(12, 62) * (1.0 - 0.45 * max(0.0, s - 0.85) / 0.15)
                    for pair in (0, 1):
                        ang = math.radians(ang0 + pair * side * rng.uniform(5, 14))
                        vx = ux * math.cos(ang) - uy * math.sin(ang)
                        vy = ux * math.sin(ang) + uy * math.cos(ang)
                        nl = rng.uniform(0.20, 0.30) * (1.0 - 0.25 * abs(ang) / math.radians(70))
                        # bent a little: the second half turned by the twist
                        tw = math.radians(rng.uniform(-9, 9))
                        wx = vx * math.cos(tw) - vy * math.sin(tw)
                        wy = vx * math.sin(tw) + vy * math.cos(tw)
                        f = 1.0
                        for _ in range(10):  # kept inside the tile
                            mx, my = px + vx * nl * 0.5 * f, py + vy * nl * 0.5 * f
                            ex, ey = mx + wx * nl * 0.5 * f, my + wy * nl * 0.5 * f
                            if 0.01 <= ex <= 0.99 and 0.01 <= ey <= 0.99:
                                break
                            f *= 0.85
                        tone = base * rng.uniform(0.78, 1.18)
                        mid = tone * 0.95
                        segs.append((px, py, mx, my, 0.0062, tone * 0.55, mid))
                        segs.append((mx, my, ex, ey, 0.0048, mid, np.minimum(tone * 1.4, 1)))
        else:  # spruce
            top = rng.uniform(0.86, 0.96)
            axes = [(0.5, 0.0, 0.5 + bend, top, 1.0)]
            n_side = int(rng.integers(4, 7))
            for i in range(n_side):
                t0 = 0.10 + 0.68 * (i + rng.uniform(0.0, 0.4)) / n_side
                side = 1 if (i + k) % 2 else -1
                a = math.radians(rng.uniform(40, 62))
                L = rng.uniform(0.32, 0.46) * (1 - 0.5 * t0)
                x0 = 0.5 + bend * t0
                axes.append((x0, t0, x0 + side * math.sin(a) * L, t0 + math.cos(a) * L, 0.75))
            for (x0, y0, x1, y1, w) in axes:
                x1 = float(np.clip(x1, 0.06, 0.94))
                segs_twig.append((x0, y0, x1, y1, 0.007 * w))
                ux, uy = x1 - x0, y1 - y0
                ln = math.hypot(ux, uy)
                ux, uy = ux / ln, uy / ln
                n = int(190 * ln * scale)
                for j in range(n):
                    s = (j + rng.random()) / n
                    px, py = x0 + (x1 - x0) * s, y0 + (y1 - y0) * s
                    for side in (-1, 1):
                        # all round the shoot (issue #44: mirrored pairs at one angle drew a
                        # flat comb that read as a lobed leaf): each needle at its own angle,
                        # foreshortened when it points toward or away from the viewer
                        ang = math.radians(rng.uniform(25, 100)) * side
                        vx = ux * math.cos(ang) - uy * math.sin(ang)
                        vy = ux * math.sin(ang) + uy * math.cos(ang)
                        nl = rng.uniform(0.065, 0.09) * w * (1 - 0.35 * s) * rng.uniform(0.4, 1.0)
                        ex = float(np.clip(px + vx * nl, 0.01, 0.99))
                        ey = float(np.clip(py + vy * nl, 0.01, 0.99))
                        # the shoot's new growth (its last fifth) lighter
                        tone = base * rng.uniform(0.8, 1.15) * (1.35 if s > 0.8 else 1.0)
                        segs.append((px, py, ex, ey, 0.0042, tone * 0.75, np.minimum(tone * 1.25, 1)))
        sub_rgb = rgb[oy:oy + tile, ox:ox + tile]
        sub_a = alpha[oy:oy + tile, ox:ox + tile]
        draw_needles(sub_rgb, sub_a, [(*P(x0, y0), *P(x1, y1), w * T, twig, twig * 0.8)
                                      for (x0, y0, x1, y1, w) in segs_twig])
        order = rng.permutation(len(segs))
        draw_needles(sub_rgb, sub_a, [(*P(segs[i][0], segs[i][1]), *P(segs[i][2], segs[i][3]),
                                       segs[i][4] * T, segs[i][5], segs[i][6]) for i in order])
    return rgb, alpha


def needle_atlas(name, kind, leaf, seed, base, twig=(0.36, 0.25, 0.16), size=512):
    """A conifer's needle-cluster atlas: needle_sprays' seven tiles and the species' shoot card
    (\p leaf) as the single leaf, denser until the sprays are about as opaque as the shoot."""
    tile = size * SS // ATLAS_ROWS
    target = float(leaf[..., 3].mean())
    for scale in (1.0, 1.3, 1.7, 2.2):
        rgb, alpha = needle_sprays(kind, seed, base, twig, tile, scale)
        if sprays_alpha(alpha, tile) >= 0.9 * target:
            break
    single_leaf_tile(rgb, alpha, leaf, tile)
    return write_atlas(name, rgb, alpha, size)


# ----------------------------------------------------------------------------- the library

def library():
    save_bark("english-oak_bark.png", bark_furrowed(101, (0.09, 0.08, 0.07), (0.50, 0.46, 0.40), ridges=5, cracks=0.9))
    leaf = simple_leaf("english-oak_leaf.png", 128, 256, oak_width, (0.20, 0.33, 0.10), 102, stem=0.05, veins=5, vein_angle=0.4)
    cluster_atlas("english-oak_leafcluster.png", leaf, 0.5, 103)

    save_bark("silver-birch_bark.png", bark_birch(), strength=3.0)
    leaf = simple_leaf("silver-birch_leaf.png", 128, 256, birch_width, (0.36, 0.55, 0.14), 112, stem=0.12, veins=8, vein_angle=0.5)
    cluster_atlas("silver-birch_leafcluster.png", leaf, 0.5, 113)

    save_bark("european-beech_bark.png", bark_smooth(121, (0.56, 0.57, 0.55), 1.0, lenticels=0.3, rings=0.6), strength=2.5)
    leaf = simple_leaf("european-beech_leaf.png", 128, 256, beech_width, (0.26, 0.46, 0.11), 122, stem=0.07, veins=7, vein_angle=0.35, gloss=0.2)
    cluster_atlas("european-beech_leafcluster.png", leaf, 0.5, 123)

    save_bark("norway-maple_bark.png", bark_furrowed(131, (0.16, 0.14, 0.12), (0.48, 0.44, 0.38), ridges=11, depth=0.6, warp=0.2, cracks=0.2))
    leaf = maple_leaf("norway-maple_leaf.png", 256, 256, (0.24, 0.48, 0.10), 132)
    cluster_atlas("norway-maple_leafcluster.png", leaf, 1.0, 133)

    save_bark("weeping-willow_bark.png", bark_furrowed(141, (0.13, 0.11, 0.09), (0.50, 0.45, 0.36), ridges=7, warp=0.8, cracks=0.4))
    leaf = simple_leaf("weeping-willow_leaf.png", 64, 256, willow_width, (0.47, 0.60, 0.22), 142, stem=0.03, veins=12, vein_angle=0.2)
    cluster_atlas("weeping-willow_leafcluster.png", leaf, 0.25, 143)

    save_bark("lombardy-poplar_bark.png", bark_furrowed(151, (0.10, 0.10, 0.09), (0.42, 0.41, 0.38), ridges=8, warp=0.3, cracks=0.6))
    leaf = simple_leaf("lombardy-poplar_leaf.png", 128, 256, poplar_width, (0.24, 0.46, 0.10), 152, stem=0.15, veins=6, vein_angle=0.5)
    cluster_atlas("lombardy-poplar_leafcluster.png", leaf, 0.5, 153)

    save_bark("scots-pine_bark.png", bark_pine(161))
    # Needle greens less teal than they were (issue #44: blue 0.8 of green read as teal)
    leaf = pine_shoot("scots-pine_leaf.png", 256, 256, (0.28, 0.42, 0.26), 162)
    needle_atlas("scots-pine_leafcluster.png", "pine", leaf, 163, (0.22, 0.34, 0.20))

    save_bark("norway-spruce_bark.png", bark_plates(171, (0.48, 0.33, 0.24), (0.16, 0.11, 0.08), count=160, stretch=(1.0, 0.8), flaky=0.8))
    leaf = sprig("norway-spruce_leaf.png", 128, 256, (0.11, 0.27, 0.11), 172)
    needle_atlas("norway-spruce_leafcluster.png", "spruce", leaf, 173, (0.14, 0.31, 0.15))

    save_bark("date-palm_bark.png", bark_palm())
    frond("date-palm_leaf.png", 128, 256, (0.30, 0.48, 0.16), 182)

    save_bark("italian-cypress_bark.png", bark_stringy(191, (0.16, 0.12, 0.10), (0.55, 0.46, 0.38)))
    leaf = scale_spray("italian-cypress_leaf.png", 128, 256, (0.13, 0.28, 0.11), 192)
    cluster_atlas("italian-cypress_leafcluster.png", leaf, 0.5, 193, count=(3, 5))

    save_bark("rhododendron_bark.png", bark_smooth(201, (0.42, 0.34, 0.27), 0.8, lenticels=0.2), strength=2.5)
    # No cluster atlas: the card is already a rosette of leaves under a truss, one at each
    # shoot tip (1,300 cards); sprays of rosettes read as stretched smears (tried).
    rhododendron("rhododendron_leaf.png", 256, 256, (0.12, 0.27, 0.08), (0.85, 0.35, 0.62), 202)

    save_bark("privet-hedge_bark.png", bark_smooth(211, (0.45, 0.42, 0.36), 0.6, lenticels=0.6), strength=2.5)
    leaf = privet("privet-hedge_leaf.png", 128, 256, (0.16, 0.36, 0.08), 212)
    cluster_atlas("privet-hedge_leafcluster.png", leaf, 0.5, 213, count=(4, 7))


# ----------------------------------------------------------------------------- seasons
# The deciduous species' leaves in spring and autumn: "<leaf>_spring.png" and
# "<leaf>_autumn.png" beside the summer leaf (the engine's seasonTextureFile picks them). The
# same drawing as the summer leaf (library(), same arguments), recoloured: spring a lighter,
# yellower green; autumn the species' own colour (tube_mesh's autumn_color in its preset),
# blotched with a darker, browner tone. Winter has no leaves.

PRESETS = os.path.dirname(HERE)
SPRING = np.asarray((0.40, 0.60, 0.15))


# The cluster atlas of each deciduous species: library()'s cluster_atlas arguments (the leaf
# card's aspect and the sprays' seed).
CLUSTERS = {"english-oak": (0.5, 103), "silver-birch": (0.5, 113), "european-beech": (0.5, 123),
            "norway-maple": (1.0, 133), "weeping-willow": (0.25, 143),
            "lombardy-poplar": (0.5, 153)}


# A real autumn crown mixes leaves at different stages: each deciduous species' autumn cluster
# atlas picks its sprays' leaves from a palette, the preset's autumn_color first (the commonest)
# and the species' other autumn tones after it, with their weights (field guides' descriptions:
# the oak's russet, tawny and olive late leaves; the beech's copper, gold and brown; the
# maple's orange, yellow and red; birch, poplar and willow yellows, golds and lingering greens).
AUTUMN_PALETTES = {
    "english-oak": [((0.62, 0.47, 0.16), 0.25), ((0.38, 0.22, 0.09), 0.2), ((0.44, 0.42, 0.15), 0.15)],
    "european-beech": [((0.84, 0.56, 0.14), 0.25), ((0.52, 0.27, 0.10), 0.2), ((0.76, 0.64, 0.22), 0.1)],
    "norway-maple": [((0.95, 0.78, 0.14), 0.3), ((0.82, 0.26, 0.07), 0.15), ((0.70, 0.66, 0.16), 0.1)],
    "silver-birch": [((0.93, 0.60, 0.12), 0.25), ((0.66, 0.70, 0.22), 0.2), ((0.74, 0.50, 0.15), 0.1)],
    "lombardy-poplar": [((0.92, 0.58, 0.12), 0.25), ((0.64, 0.68, 0.20), 0.2), ((0.78, 0.80, 0.30), 0.1)],
    "weeping-willow": [((0.88, 0.76, 0.16), 0.3), ((0.56, 0.62, 0.22), 0.2), ((0.80, 0.60, 0.15), 0.1)],
}


def autumn_palette(species, rgba, main):
    """The autumn leaf drawing \p rgba (recoloured to \p main) and its palette variants, with
    their weights: each variant keeps the drawing's shading and blotches, moved from \p main to
    its own colour."""
    tones = AUTUMN_PALETTES.get(species, [])
    leaves, weights = [rgba], [1.0 - sum(w for _, w in tones)]
    for colour, weight in tones:
        v = rgba.copy()
        v[..., :3] = np.clip(rgba[..., :3] * (np.asarray(colour) / np.maximum(main, 1e-3)), 0, 1)
        leaves.append(v)
        weights.append(weight)
    return leaves, weights


def deciduous_leaf(species, name):
    """Draws \p species' leaf (library()'s call) under \p name and returns its RGBA."""
    if species == "english-oak":
        return simple_leaf(name, 128, 256, oak_width, (0.20, 0.33, 0.10), 102, stem=0.05, veins=5, vein_angle=0.4)
    elif species == "silver-birch":
        return simple_leaf(name, 128, 256, birch_width, (0.36, 0.55, 0.14), 112, stem=0.12, veins=8, vein_angle=0.5)
    elif species == "european-beech":
        return simple_leaf(name, 128, 256, beech_width, (0.26, 0.46, 0.11), 122, stem=0.07, veins=7, vein_angle=0.35, gloss=0.2)
    elif species == "norway-maple":
        return maple_leaf(name, 256, 256, (0.24, 0.48, 0.10), 132)
    elif species == "weeping-willow":
        return simple_leaf(name, 64, 256, willow_width, (0.47, 0.60, 0.22), 142, stem=0.03, veins=12, vein_angle=0.2)
    elif species == "lombardy-poplar":
        return simple_leaf(name, 128, 256, poplar_width, (0.24, 0.46, 0.10), 152, stem=0.15, veins=6, vein_angle=0.5)
    else:
        raise ValueError("no deciduous leaf drawing for " + species)


def season_settings(species):
    """(deciduous, autumn colour) from the tube_mesh node of presets/<species>.json."""
    import json
    with open(os.path.join(PRESETS, species + ".json")) as f:
        graph = json.load(f)["graph"]
    for node in graph["nodes"]:
        if node["type"] == "tube_mesh":
            p = node.get("params", {})
            return bool(p.get("deciduous", False)), p.get("autumn_color")
    return False, None


def recolor_to(target, seed, blotch=None):
    """A SEASON_RECOLOR that moves a leaf from its summer green to \p target, keeping its
    shading (the ratio to the leaf's mean colour), with \p blotch patches when given."""
    target = np.asarray(target, np.float64)

    def recolor(rgb, mask):
        m = mask.astype(bool)
        mean = rgb[m].mean(axis=0) if m.any() else np.full(3, 0.5)
        shade = (rgb / np.maximum(mean, 1e-3)).mean(axis=-1, keepdims=True)
        col = np.broadcast_to(target, rgb.shape)
        if blotch is not None:
            n = noise(mask.shape, 30, 30, seed)
            k = np.clip((n - 0.45) * 4, 0, 1)[..., None]
            col = col * (1 - k) + np.asarray(blotch) * k
        return col * shade

    return recolor


def seasons():
    global SEASON_RECOLOR
    for species in ("english-oak", "european-beech", "norway-maple", "silver-birch",
                    "lombardy-poplar", "weeping-willow"):
        deciduous, autumn = season_settings(species)
        if not deciduous or autumn is None:
            continue
        leaf = species + "_leaf"
        autumn = np.asarray(autumn, np.float64)
        try:
            # Autumn leaves are not one colour: patches turn darker and browner first.
            for season, recolor in (("spring", recolor_to(SPRING, 0)),
                                    ("autumn", recolor_to(autumn, 7, autumn * 0.55 +
                                                          np.asarray((0.08, 0.04, 0.01))))):
                SEASON_RECOLOR = recolor
                rgba = deciduous_leaf(species, leaf + "_" + season + ".png")
                # The season's cluster atlas: the same sprays (same seed) of the season's leaf;
                # already recoloured, so kept as it is, and like the leaf it shares the summer
                # atlas's normal and roughness maps.
                if species in CLUSTERS:
                    SEASON_RECOLOR = lambda rgb, mask: rgb
                    aspect, seed = CLUSTERS[species]
                    palette = None
                    if season == "autumn":
                        leaves, weights = autumn_palette(species, rgba, autumn)
                        palette = (leaves, weights, seed + 1000)
                    cluster_atlas(species + "_leafcluster_" + season + ".png", rgba, aspect, seed,
                                  palette=palette)
        finally:
            SEASON_RECOLOR = None


def main(argv):
    which = set(argv[1:]) or {"--library", "--defaults"}
    unknown = which - {"--library", "--defaults"}
    if unknown:
        sys.exit("usage: make_textures.py [--library] [--defaults]")
    if "--library" in which:
        library()
        seasons()
    if "--defaults" in which:
        default_bark(os.path.join(DEFAULTS, "bark.png"))
        default_leaf(os.path.join(DEFAULTS, "leaf.png"))


if __name__ == "__main__":
    main(sys.argv)
