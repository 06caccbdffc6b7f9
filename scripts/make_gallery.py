#!/usr/bin/python3
"""Renders the species library with Sylva's own viewport and writes docs/gallery/*.png and the
generated tables of docs/gallery.md (between the `gallery:begin` / `gallery:end` markers).

Each species is drawn at three seeds: a copy of its file with every generator's `seed`
parameter set (the editor evaluates a species with its own seeds) is shown by
`sylva --screenshot` under Xvfb; triangles come from `sylva-cli tree --stats`. Needs Debian's
xvfb, python3-pil and a release build.

  /usr/bin/python3 scripts/make_gallery.py [--build build/release] [--only english-oak,...]
      [--seeds 1,2,3] [--out docs/gallery] [--size 480] [--thumb 240] [--no-doc]
      [--seasons] [--closeups]   (only the season strips / only the close-ups)
      [--tints]   (only the leaf colour strips: before and after, summer and autumn)
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The species library, in the gallery's order.
SPECIES = [
    "english-oak", "silver-birch", "european-beech", "norway-maple", "weeping-willow",
    "lombardy-poplar", "scots-pine", "norway-spruce", "date-palm", "italian-cypress",
    "rhododendron", "privet-hedge",
]
GENERATORS = ("lsystem", "space_colonization", "self_organizing")


def seeded_copy(species, seed, folder):
    """The species file with absolute file parameters and every generator seeded."""
    path = os.path.join(ROOT, "presets", species + ".json")
    with open(path) as f:
        doc = json.load(f)
    base = os.path.dirname(path)

    def absolutize(params):
        for key, value in list(params.items()):
            if isinstance(value, str) and (key == "file" or key.endswith("_file")):
                params[key] = os.path.normpath(os.path.join(base, value))
            elif isinstance(value, dict):
                absolutize(value)

    for node in doc["graph"]["nodes"]:
        params = node.setdefault("params", {})
        absolutize(params)
        if node["type"] in GENERATORS:
            params["seed"] = seed
    out = os.path.join(folder, "%s-%d.json" % (species, seed))
    with open(out, "w") as f:
        json.dump(doc, f)
    return out


def render(build, species_file, png, size):
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
           os.path.join(build, "app/editor/sylva"), "--screenshot", png,
           "--size", "%dx%d" % (size, size), species_file]
    env = dict(os.environ, SYLVA_MSAA="4", LC_ALL="C")
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=env)


# Close-ups in the editor's viewport (camera eye, target in metres): the bark and the leaf
# cards at a size where their textures show.
CLOSEUPS = [
    ("silver-birch", (2.2, 3.2, 4.5), (0.0, 4.0, 0.0)),
    ("english-oak", (3.5, 2.0, 6.0), (0.0, 3.2, 0.0)),
    ("scots-pine", (4.5, 10.5, 6.5), (0.0, 11.5, 0.0)),
    # issue #33: the pine's needle tufts, the spruce's sprays, the rhododendron's trusses
    ("scots-pine", (2.5, 11.0, 3.5), (0.0, 12.0, 0.0), "scots-pine-needles"),
    ("norway-spruce", (3.0, 4.0, 5.0), (0.0, 3.5, 0.0)),
    ("rhododendron", (2.2, 2.0, 2.6), (0.0, 1.4, 0.0)),
]


# The bark alone, near enough for the normal map's relief to show (issue #33).
BARK_CLOSEUPS = [
    ("english-oak", (0.9, 1.4, 1.3), (0.0, 1.2, 0.0)),
    ("scots-pine", (0.7, 1.6, 1.0), (0.0, 1.5, 0.0)),
]

SEASONS = ("spring", "summer", "autumn", "winter")


def season_copy(species, season, folder, seed=1):
    """seeded_copy() with the tube_mesh's season set."""
    path = seeded_copy(species, seed, folder)
    with open(path) as f:
        doc = json.load(f)
    for node in doc["graph"]["nodes"]:
        if node["type"] == "tube_mesh":
            node.setdefault("params", {})["season"] = season
    out = os.path.join(folder, "%s-%s.json" % (species, season))
    with open(out, "w") as f:
        json.dump(doc, f)
    return out


def season_strip(build, species, folder, dst, size, thumb):
    """The species in its four seasons side by side, each labelled."""
    from PIL import ImageDraw
    tiles = []
    for season in SEASONS:
        raw = os.path.join(folder, "%s-%s.png" % (species, season))
        render(build, season_copy(species, season, folder), raw, size)
        img = Image.open(raw).convert("RGB")
        img.thumbnail((thumb, thumb), Image.LANCZOS)
        ImageDraw.Draw(img).text((6, 4), season, fill=(20, 20, 20))
        tiles.append(img)
    strip = Image.new("RGB", (sum(t.width for t in tiles), max(t.height for t in tiles)))
    x = 0
    for t in tiles:
        strip.paste(t, (x, 0))
        x += t.width
    strip = strip.quantize(colors=192, method=Image.MEDIANCUT, dither=Image.FLOYDSTEINBERG)
    strip.save(dst, optimize=True)


# Leaf colour variation (issue #33): these species, before (variation 0) and after, in summer
# and autumn, from the gallery's camera and from nearer (TINT_CLOSE: eye, target in metres).
TINT_SPECIES = ("english-oak", "european-beech", "norway-maple")
TINT_CLOSE = {"english-oak": ((7.0, 5.0, 13.0), (0.0, 6.0, 0.0)),
              "european-beech": ((6.0, 9.0, 11.0), (0.0, 9.5, 0.0)),
              "norway-maple": ((6.0, 7.0, 11.0), (0.0, 7.5, 0.0))}


def tint_copy(species, season, tinted, folder):
    """season_copy() with the leaf colour variation and light shading kept (tinted) or set to
    zero."""
    path = season_copy(species, season, folder)
    with open(path) as f:
        doc = json.load(f)
    for node in doc["graph"]["nodes"]:
        if node["type"] == "tube_mesh" and not tinted:
            for key in list(node["params"]):
                if key.endswith("_variation") or key == "leaf_light_shading":
                    node["params"][key] = 0
    out = os.path.join(folder, "%s-%s-%s.json" % (species, season, "on" if tinted else "off"))
    with open(out, "w") as f:
        json.dump(doc, f)
    return out


def tint_strip(build, species, folder, dst, size):
    """Summer without and with the variation, autumn without and with; whole tree above, a
    nearer view of the crown below, each labelled."""
    from PIL import ImageDraw
    rows = [[], []]
    for season in ("summer", "autumn"):
        for tinted in (False, True):
            f = tint_copy(species, season, tinted, folder)
            label = "%s, %s" % (season, "varied" if tinted else "one tint")
            raw = os.path.join(folder, "%s-%s-%d.png" % (species, season, tinted))
            render(build, f, raw, size)
            near = os.path.join(folder, "%s-%s-%d-near.png" % (species, season, tinted))
            eye, target = TINT_CLOSE[species]
            script = os.path.join(folder, "near.py")
            with open(script, "w") as out:
                out.write("import sylva\nwin = sylva.window()\nwin.look_from(%r, %r)\n"
                          "win.screenshot(%r, viewport_only=True)\n" % (eye, target, near))
            subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                            os.path.join(build, "app/editor/sylva"), "--size",
                            "%dx%d" % (size, size), "--script", script, f],
                           check=True, stdout=subprocess.DEVNULL,
                           env=dict(os.environ, LC_ALL="C", SYLVA_MSAA="4"))
            for row, src in zip(rows, (raw, near)):
                img = Image.open(src).convert("RGB")
                img.thumbnail((size // 2, size // 2), Image.LANCZOS)
                ImageDraw.Draw(img).text((6, 4), label, fill=(20, 20, 20))
                row.append(img)
    w, h = rows[0][0].width, rows[0][0].height
    strip = Image.new("RGB", (4 * w, 2 * h))
    for j, row in enumerate(rows):
        for i, img in enumerate(row):
            strip.paste(img, (i * w, j * h))
    strip.save(dst, optimize=True)


def seasons_doc(species):
    lines = ["| species | spring · summer · autumn · winter |", "|---|---|"]
    for sp in species:
        with open(os.path.join(ROOT, "presets", sp + ".json")) as f:
            doc = json.load(f)
        mesh = [n for n in doc["graph"]["nodes"] if n["type"] == "tube_mesh"][0]
        params = mesh.get("params", {})
        kind = ("deciduous, autumn colour %s" % params["autumn_color"]
                if params.get("deciduous") else "evergreen: the same all year")
        lines.append("| **%s**<br>%s | ![%s in spring, summer, autumn and winter]"
                     "(gallery/seasons-%s.png) |" % (doc["name"], kind, doc["name"], sp))
    doc_path = os.path.join(ROOT, "docs", "gallery.md")
    with open(doc_path) as f:
        text = f.read()
    begin, end = "<!-- seasons:begin -->", "<!-- seasons:end -->"
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    with open(doc_path, "w") as f:
        f.write(head + begin + "\n" + "\n".join(lines) + "\n" + end + tail)


def closeup(build, species, eye, target, png, folder):
    script = os.path.join(folder, "closeup.py")
    with open(script, "w") as f:
        f.write("import sylva\nwin = sylva.window()\nwin.look_from(%r, %r)\n"
                "win.screenshot(%r, viewport_only=True)\n" % (eye, target, png))
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
           os.path.join(build, "app/editor/sylva"), "--size", "640x480", "--script", script,
           seeded_copy(species, 1, folder)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, SYLVA_MSAA="4", LC_ALL="C"))


def library(build, png, folder, project="resources/demo/library.sylva"):
    """A whole project (the library by default), seen from its camera."""
    with open(os.path.join(ROOT, project)) as f:
        camera = json.load(f)["camera"]
    script = os.path.join(folder, os.path.basename(project) + ".py")
    with open(script, "w") as f:
        f.write("import sylva\nwin = sylva.window()\nwin.look_from(%r, %r)\n"
                "win.screenshot(%r, viewport_only=True)\n"
                % (tuple(camera["position"]), tuple(camera["target"]), png))
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1600x1000x24",
           os.path.join(build, "app/editor/sylva"), "--size", "1200x600", "--script", script,
           os.path.join(ROOT, project)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, SYLVA_MSAA="4", LC_ALL="C"))


def solidity(build):
    """The broadleaves' crown silhouette table printed by test_crownshape (issue #33)."""
    out = subprocess.run([os.path.join(build, "tests/core/forest/test_crownshape"),
                          "--gtest_filter=CrownShape.Broadleaves*"], check=True, capture_output=True,
                         text=True).stdout
    return [l for l in out.splitlines() if l.startswith("|")]


def leaf_clusters(build):
    """The leaf cluster table printed by test_crownshape's LeafClusters tests: the broadleaves,
    then the conifers and shrubs (one header)."""
    out = subprocess.run([os.path.join(build, "tests/core/forest/test_crownshape"),
                          "--gtest_filter=LeafClusters.Broad*:LeafClusters.Conifers*"],
                         check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        if line.startswith("|") and line not in rows:
            rows.append(line)
    return rows


def triangles(build, species_file, folder):
    out = subprocess.run([os.path.join(build, "app/cli/sylva-cli"), "tree", species_file, "-o",
                          os.path.join(folder, "t.obj"), "--stats"],
                         check=True, capture_output=True, text=True).stdout
    stats = json.loads(out.strip().splitlines()[-1])
    return int(stats["triangles"]), float(stats.get("height", 0.0))


def thumbnail(src, dst, thumb, colors=192):
    img = Image.open(src).convert("RGB")
    img.thumbnail((thumb, thumb), Image.LANCZOS)
    img = img.quantize(colors=colors, method=Image.MEDIANCUT, dither=Image.FLOYDSTEINBERG)
    img.save(dst, optimize=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build/release"))
    ap.add_argument("--only", default="")
    ap.add_argument("--seeds", default="1,2,3")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs/gallery"))
    ap.add_argument("--size", type=int, default=480)
    ap.add_argument("--thumb", type=int, default=240)
    ap.add_argument("--no-doc", action="store_true", help="do not rewrite docs/gallery.md")
    ap.add_argument("--seasons", action="store_true",
                    help="only the season strips (docs/gallery/seasons-*.png, the seasons table)")
    ap.add_argument("--closeups", action="store_true", help="only the close-ups")
    ap.add_argument("--tints", action="store_true",
                    help="only the leaf colour strips (docs/gallery/tints-*.png)")
    args = ap.parse_args()
    if args.tints:
        species = [s for s in args.only.split(",") if s] if args.only else TINT_SPECIES
        os.makedirs(args.out, exist_ok=True)
        with tempfile.TemporaryDirectory() as tmp:
            for sp in species:
                tint_strip(args.build, sp, tmp, os.path.join(args.out, "tints-%s.png" % sp),
                           args.size)
                print(sp, "tints", file=sys.stderr)
        return
    if args.seasons or args.closeups:
        species = [s for s in args.only.split(",") if s] if args.only else SPECIES
        os.makedirs(args.out, exist_ok=True)
        with tempfile.TemporaryDirectory() as tmp:
            if args.seasons:
                for sp in species:
                    season_strip(args.build, sp, tmp,
                                 os.path.join(args.out, "seasons-%s.png" % sp), args.size, 200)
                    print(sp, "seasons", file=sys.stderr)
                if not args.no_doc and not args.only:
                    seasons_doc(species)
            if args.closeups:
                for sp, eye, target, *name in CLOSEUPS:
                    out = name[0] if name else "%s-closeup" % sp
                    raw = os.path.join(tmp, "%s.png" % out)
                    closeup(args.build, sp, eye, target, raw, tmp)
                    thumbnail(raw, os.path.join(args.out, "%s.png" % out), 360, colors=96)
                for sp, eye, target in BARK_CLOSEUPS:
                    raw = os.path.join(tmp, "%s-bark.png" % sp)
                    closeup(args.build, sp, eye, target, raw, tmp)
                    thumbnail(raw, os.path.join(args.out, "%s-bark.png" % sp), 480, colors=160)
        return
    species = ([s for s in args.only.split(",") if s and s not in ("stand", "demo")]
               if args.only else SPECIES)
    seeds = [int(s) for s in args.seeds.split(",")]
    os.makedirs(args.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for sp in species:
            tris = []
            for seed in seeds:
                f = seeded_copy(sp, seed, tmp)
                raw = os.path.join(tmp, "%s-%d.png" % (sp, seed))
                render(args.build, f, raw, args.size)
                thumbnail(raw, os.path.join(args.out, "%s-%d.png" % (sp, seed)), args.thumb)
                tris.append(triangles(args.build, f, tmp))
                print(sp, seed, tris[-1], file=sys.stderr)
            rows.append((sp, tris))
        for sp, eye, target, *name in CLOSEUPS:
            if sp not in species:
                continue
            out = name[0] if name else "%s-closeup" % sp
            raw = os.path.join(tmp, "%s.png" % out)
            closeup(args.build, sp, eye, target, raw, tmp)
            thumbnail(raw, os.path.join(args.out, "%s.png" % out), 360, colors=96)
        if not args.only:
            raw = os.path.join(tmp, "library.png")
            library(args.build, raw, tmp)
            thumbnail(raw, os.path.join(args.out, "library.png"), 720, colors=128)
        if not args.only or "demo" in args.only.split(","):
            raw = os.path.join(tmp, "demo.png")
            library(args.build, raw, tmp, "resources/demo/forest.sylva")
            thumbnail(raw, os.path.join(args.out, "demo.png"), 720, colors=160)
        if not args.only or "stand" in args.only.split(","):
            raw = os.path.join(tmp, "stand.png")
            library(args.build, raw, tmp, "resources/demo/stand.sylva")
            thumbnail(raw, os.path.join(args.out, "stand.png"), 720, colors=128)
    if args.no_doc or args.only:
        return
    lines = ["| species | seed %s |" % " | seed ".join(map(str, seeds)),
             "|---|" + "---|" * len(seeds)]
    for sp, tris in rows:
        with open(os.path.join(ROOT, "presets", sp + ".json")) as f:
            name = json.load(f)["name"]
        cells = ["![%s, seed %d](gallery/%s-%d.png)" % (name, s, sp, s) for s in seeds]
        lines.append("| **%s**<br>`presets/%s.json` | %s |" % (name, sp, " | ".join(cells)))
    lines += ["", "| species | triangles (seeds %s) | height (m) |" % ", ".join(map(str, seeds)),
              "|---|---|---|"]
    for sp, tris in rows:
        lines.append("| %s | %s | %s |" % (sp, " / ".join("{:,}".format(t) for t, _ in tris),
                                           " / ".join("%.1f" % h for _, h in tris)))
    lines += ["", "Crown silhouettes of the broadleaves (`tests/core/forest/test_crownshape`: side view,"
              " crown rows, solidity = area / convex hull area, the mean of two views; it asserts"
              " <= 0.85; middle cover: how much of the crown's middle is covered, it asserts >= 0.6"
              " for maple, birch and beech):", ""] + solidity(args.build)
    lines += ["", "Leaf clusters of the broadleaves, then of the conifers and the privet"
              " (`test_leafclusters`, seed 1: leaf-card triangles with one card a leaf and with"
              " cluster cards, and the silhouettes' IoU, conservative raster; it asserts a ratio"
              " >= 4 and IoU >= 0.92 for the broadleaves, >= 0.9 for the others):", ""]
    lines += leaf_clusters(args.build)
    doc_path = os.path.join(ROOT, "docs", "gallery.md")
    with open(doc_path) as f:
        text = f.read()
    begin, end = "<!-- gallery:begin -->", "<!-- gallery:end -->"
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    with open(doc_path, "w") as f:
        f.write(head + begin + "\n" + "\n".join(lines) + "\n" + end + tail)


if __name__ == "__main__":
    main()
