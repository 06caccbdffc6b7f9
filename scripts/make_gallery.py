#!/usr/bin/python3
"""Renders the species library with Sylva's own viewport and writes docs/gallery/*.png and the
generated tables of docs/gallery.md (between the `gallery:begin` / `gallery:end` markers).

Each species is drawn at three seeds: a copy of its file with every generator's `seed`
parameter set (the editor evaluates a species with its own seeds) is shown by
`sylva --screenshot` under Xvfb; triangles come from `sylva-cli tree --stats`. Needs Debian's
xvfb, python3-pil and a release build.

  /usr/bin/python3 scripts/make_gallery.py [--build build/release] [--only english-oak,...]
      [--seeds 1,2,3] [--out docs/gallery] [--size 480] [--thumb 240] [--no-doc]
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
]


def closeup(build, species, eye, target, png, folder):
    script = os.path.join(folder, "closeup.py")
    with open(script, "w") as f:
        f.write("import sylva\nwin = sylva.window()\nwin.look_from(%r, %r)\n"
                "win.screenshot(%r, viewport_only=True)\n" % (eye, target, png))
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
           os.path.join(build, "app/editor/sylva"), "--size", "640x480", "--script", script,
           seeded_copy(species, 1, folder)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, LC_ALL="C"))


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
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, LC_ALL="C"))


def solidity(build):
    """The broadleaves' crown silhouette table printed by test_crownshape (issue #33)."""
    out = subprocess.run([os.path.join(build, "tests/core/forest/test_crownshape"),
                          "--gtest_filter=CrownShape.Broadleaves*"], check=True, capture_output=True,
                         text=True).stdout
    return [l for l in out.splitlines() if l.startswith("|")]


def leaf_clusters(build):
    """The broadleaves' leaf cluster table printed by test_crownshape's LeafClusters test."""
    out = subprocess.run([os.path.join(build, "tests/core/forest/test_crownshape"),
                          "--gtest_filter=LeafClusters.Broad*"], check=True, capture_output=True,
                         text=True).stdout
    return [l for l in out.splitlines() if l.startswith("|")]


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
    args = ap.parse_args()
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
        for sp, eye, target in CLOSEUPS:
            if sp not in species:
                continue
            raw = os.path.join(tmp, "%s-closeup.png" % sp)
            closeup(args.build, sp, eye, target, raw, tmp)
            thumbnail(raw, os.path.join(args.out, "%s-closeup.png" % sp), 360, colors=96)
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
    lines += ["", "Leaf clusters of the broadleaves (`test_leafclusters`, seed 1: leaf-card triangles"
              " with one card a leaf and with cluster cards, and the silhouettes' IoU, conservative"
              " raster; it asserts a ratio >= 4 and IoU >= 0.9):", ""] + leaf_clusters(args.build)
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
