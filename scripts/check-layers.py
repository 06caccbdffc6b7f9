#!/usr/bin/env python3
"""Checks the include graph between the code's rooms against the layering ARCHITECTURE.md
draws: every `#include "engine/<folder>/..."` inside core/engine and every
`#include "ui/<folder>/..."` inside ui/ must follow an arrow of ALLOWED below, and the engine
must include no Qt, the document no Qt Widgets. Prints each edge that breaks the rule with the
file and line, and exits 1. Usage: check-layers.py [repository root]
"""
import os
import re
import sys

# folder -> the folders it includes directly: the arrows of ARCHITECTURE.md's engine diagram
# ("every room -> skeleton -> util" included). A room may include every room it reaches along
# them (closure() below). An arrow added here is a design decision: draw it there and say why.
ARROWS = {
    "util": set(),
    "skeleton": {"util"},
    "lsystem": {"skeleton"},
    "environment": {"skeleton"},
    "mesh": {"skeleton"},
    "growth": {"environment", "skeleton"},
    "placement": {"environment", "skeleton"},
    "graph": {"mesh", "skeleton"},
    "wind": {"mesh", "skeleton"},
    "export": {"mesh", "wind", "skeleton"},
    "nodes": {"graph", "lsystem", "growth", "environment", "mesh", "wind", "skeleton"},
    "forest": {"placement", "nodes", "wind", "skeleton"},
}


def closure(arrows):
    """Every room reachable from each room along the arrows."""
    reach = {}
    for room in arrows:
        seen, todo = set(), list(arrows[room])
        while todo:
            r = todo.pop()
            if r not in seen:
                seen.add(r)
                todo.extend(arrows.get(r, ()))
        reach[room] = seen
    return reach


ENGINE = closure(ARROWS)
UI = {
    "generation": set(),
    "grammar": set(),
    "nodes": set(),
    "document": {"generation"},
    "viewport": {"generation"},
    "scripting": {"document", "generation", "nodes", "viewport", "grammar"},
}
# Across the big layers (engine < document < python/bindings < ui < app; ui/scripting builds
# the editor's module on python/bindings): what a layer must never include.
FORBIDDEN = {
    "core/engine": re.compile(r'#include\s*(<Q|"(document|ui|python|app)/)'),
    "core/document": re.compile(
        r'#include\s*(<(QWidget|QtWidgets|QMainWindow|QDialog|QAction)|"(ui|python|app)/)'),
    "ui": re.compile(r'#include\s*"app/'),
    # python/: the bindings and the module, above the document, below the editor and the apps.
    "python": re.compile(r'#include\s*"(ui|app)/'),
}


def node_type_names(root):
    """The built-in node types' names, as engine/nodes registers them."""
    names = set()
    for path in sources(os.path.join(root, "core/engine/nodes")):
        names.update(re.findall(r'\.name = "([a-z_]+)"', open(path, encoding="utf-8").read()))
    return names


def sources(folder):
    for d, _, files in os.walk(folder):
        for f in sorted(files):
            if f.endswith((".h", ".cpp")):
                yield os.path.join(d, f)


def check(root):
    problems = []
    for base, prefix, allowed in (("core/engine", "engine", ENGINE), ("ui", "ui", UI)):
        pattern = re.compile(r'#include\s*"' + prefix + r'/([a-z]+)/')
        for path in sources(os.path.join(root, base)):
            rel = os.path.relpath(path, os.path.join(root, base))
            parts = rel.split(os.sep)
            if len(parts) < 2:
                continue  # files at the top of ui/ assemble rooms: anything below them
            room = parts[0]
            if room not in allowed:
                problems.append(f"{base}/{room}: a room the layering does not know; add it to "
                                f"scripts/check-layers.py and ARCHITECTURE.md")
                continue
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                m = pattern.search(line)
                if m and m.group(1) != room and m.group(1) not in allowed[room]:
                    problems.append(f"{base}/{rel}:{n}: {room} must not include {m.group(1)}")
    for base, pattern in FORBIDDEN.items():
        for path in sources(os.path.join(root, base)):
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                if pattern.search(line):
                    problems.append(f"{os.path.relpath(path, root)}:{n}: {line.strip()} "
                                    f"is not allowed in {base}")
    # graph/ is the model and the evaluator: it knows no node type by name (types declare their
    # role, graph::NodeRole, and graph asks it).
    names = node_type_names(root)
    if names:
        quoted = re.compile(r'"(' + "|".join(sorted(names)) + r')"')
        for path in sources(os.path.join(root, "core/engine/graph")):
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                m = quoted.search(line.split("//")[0])
                if m:
                    problems.append(f"{os.path.relpath(path, root)}:{n}: the node type "
                                    f"\"{m.group(1)}\" named in graph/ (ask NodeType::role)")
    # Outside engine/nodes no code tests a node type by its name either: it asks the type's
    # traits (graph::findType, roleOf, standGrowthOf, graph::meshOutput) or, to make a default
    # graph, engine/nodes (nodes::grammarSpecies). A name used as a type: compared, assigned to
    # a `type`, the type of a NodeDesc, or looked up in the registry. (The same word as a stats
    # key or a JSON key, "adapt" or "leaves", is not a type.) Tests may name types.
    if names:
        n = "(" + "|".join(sorted(names)) + ")"
        wrap = r'(?:QLatin1String|QStringLiteral|QString|std::string)?\(?\s*'
        # Compared with something named type (a material "leaves" is not a node type).
        as_type = re.compile(r'[tT]ype\w*(?:\(\))?\s*(==|!=)\s*' + wrap + '"' + n + '"|'
                             r'"' + n + r'"\s*\)?\s*(==|!=)\s*[\w.>-]*[tT]ype|'
                             r'\btype\s*=\s*"' + n + '"|'
                             r'NodeDesc\s*\w*\s*\{\s*"[^"]*"\s*,\s*"' + n + '"|'
                             r'(findType|roleOf|standGrowthOf|NodeRegistry::instance\(\)\.find)'
                             r'\(\s*"' + n + '"')
        nodes_dir = os.path.join("core", "engine", "nodes") + os.sep
        for base in ("core", "app", "python", "ui"):
            for path in sources(os.path.join(root, base)):
                rel = os.path.relpath(path, root)
                if rel.startswith(nodes_dir):
                    continue
                for line_no, line in enumerate(open(path, encoding="utf-8"), 1):
                    m = as_type.search(line.split("//")[0])
                    if m:
                        name = next(g for g in m.groups() if g and g in names)
                        problems.append(f"{rel}:{line_no}: the node type \"{name}\" tested "
                                        f"outside engine/nodes (ask its traits: graph::findType, "
                                        f"roleOf, standGrowthOf, meshOutput)")
    # Only the format table (engine/export/formats.cpp) switches on an export format's file
    # extension; everything else asks it (formatFor, findFormat, FormatRow). Reading obstacle
    # meshes (engine/environment) is not exporting and has its own checks.
    extension = re.compile(r'(==|!=)\s*"\.(obj|usda|usdc|usd|glb|gltf|fbx)"|'
                           r'"\.(obj|usda|usdc|usd|glb|gltf|fbx)"\s*(==|!=)|'
                           r'[hH]asExtension\([^)]*"\.(obj|usda|usdc|usd|glb|gltf|fbx)"')
    for base in ("core/engine/export", "core/document", "app", "python", "ui"):
        for path in sources(os.path.join(root, base)):
            if path.endswith(os.path.join("engine", "export", "formats.cpp")):
                continue
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                if extension.search(line.split("//")[0]):
                    problems.append(f"{os.path.relpath(path, root)}:{n}: a file extension "
                                    f"tested outside the format table (engine/export/formats.h)")
    return sorted(set(problems))


if __name__ == "__main__":
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))
    found = check(root)
    for p in found:
        print(p)
    print(f"layers: {len(found)} problem(s)")
    sys.exit(1 if found else 0)
