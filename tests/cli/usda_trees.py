#!/usr/bin/env python3
"""Lists the trees of a Sylva USD stage, one line each, sorted by id:
    <id> unique <species> <translate> <rotateY> <scale>
    <id> instance <species> <protoIndex> <position> <orientation> <scale>
with the numbers exactly as written. A root layer's subLayers are followed (the composed
stage), so `diff` of two listings says whether two stages hold the same forest tree for tree.
Knows only the layout Sylva writes (docs/usd.md); the independent reader is tinyusdz.
usage: usda_trees.py LAYER.usda [--summary]
"""
import os
import re
import sys

TUPLE = re.compile(r"\(([^()]*)\)")


def array(line):
    value = line[line.index(" = ") + 3 :]
    body = value[value.index("[") + 1 : value.rindex("]")]
    if "(" in body:
        return ["(" + t.replace(" ", "") + ")" for t in TUPLE.findall(body)]
    return [t.strip() for t in body.split(",") if t.strip()]


def layer_trees(path, out, seen):
    path = os.path.normpath(path)
    if path in seen:
        raise SystemExit(f"{path}: a layer is composed twice")
    seen.add(path)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if not text.startswith("#usda 1.0"):
        raise SystemExit(f"{path}: not a USD text layer")
    header = text.split("\ndef ", 1)[0]
    m = re.search(r"subLayers = \[(.*?)\]", header, re.S)
    if m:
        for sub in re.findall(r"@([^@]+)@", m.group(1)):
            layer_trees(os.path.join(os.path.dirname(path), sub), out, seen)
    tree = None
    instancer = None
    for line in text.split("\n"):
        s = line.strip()
        mt = re.match(r'def Xform "tree_(\d+)"', s)
        if mt:
            tree = {"id": int(mt.group(1))}
            continue
        mi = re.match(r'def PointInstancer "(\w+)"', s)
        if mi:
            instancer = {"name": mi.group(1)}
            continue
        if tree is not None:
            for key, pat in (("species", r'custom string sylva:species = (".*")$'),
                             ("t", r"double3 xformOp:translate = \((.*)\)$"),
                             ("r", r"float xformOp:rotateY = (\S+)$"),
                             ("s", r"float3 xformOp:scale = \((.*)\)$")):
                mm = re.match(pat, s)
                if mm:
                    tree[key] = mm.group(1).replace(" ", "")
            if "s" in tree:
                out.append((tree["id"], f'{tree["id"]} unique {tree["species"]} ({tree["t"]}) '
                                        f'{tree["r"]} ({tree["s"]})'))
                tree = None
        if instancer is not None:
            for key, decl in (("ids", "int64[] ids"), ("o", "quath[] orientations"),
                              ("p", "point3f[] positions"), ("k", "int[] protoIndices"),
                              ("s", "float3[] scales")):
                if s.startswith(decl + " = "):
                    instancer[key] = array(s)
            if all(k in instancer for k in ("ids", "o", "p", "k", "s")):
                species = re.sub(r"_tile\d+$", "", instancer["name"])
                n = len(instancer["ids"])
                for k in ("o", "p", "k", "s"):
                    if len(instancer[k]) != n:
                        raise SystemExit(f"{path}: {instancer['name']}: {k} has "
                                         f"{len(instancer[k])} entries, ids {n}")
                for i in range(n):
                    tid = int(instancer["ids"][i])
                    out.append((tid, f"{tid} instance {species} {instancer['k'][i]} "
                                     f"{instancer['p'][i]} {instancer['o'][i]} {instancer['s'][i]}"))
                instancer = None


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    out = []
    layer_trees(sys.argv[1], out, set())
    out.sort()
    ids = [i for i, _ in out]
    if len(set(ids)) != len(ids):
        raise SystemExit("a tree id appears twice")
    if "--summary" in sys.argv:
        print(len(out), sum(1 for _, l in out if " unique " in l),
              sum(1 for _, l in out if " instance " in l))
        return
    for _, line in out:
        print(line)


main()
