"""Blender imports Sylva's normal and roughness maps: blender -b --factory-startup --python
test_normalmaps.py -- <sylva-cli> <species.json> <scratch folder>. A library oak is exported as
OBJ, GLB and FBX; each import must give the oak's bark and leaf materials a Normal Map node fed
by the exported normal map and plugged into the Principled BSDF's Normal (and, for OBJ and glTF,
an image on its Roughness). Exits 1 on failure (--python-exit-code 1)."""
import os
import subprocess
import sys

sys.dont_write_bytecode = True
import bpy
import numpy

if not hasattr(numpy, "bool"):  # Debian 12's Blender 3.4 glTF importer still uses np.bool
    numpy.bool = bool

cli, species, work = sys.argv[sys.argv.index("--") + 1:][:3]
os.makedirs(work, exist_ok=True)


def upstream_images(node, seen=None):
    """Every image reached by following \\p node's inputs upstream."""
    seen = set() if seen is None else seen
    out = []
    for socket in node.inputs:
        for link in socket.links:
            n = link.from_node
            if n.name in seen:
                continue
            seen.add(n.name)
            if n.type == "TEX_IMAGE" and n.image:
                out.append(n.image)
            out += upstream_images(n, seen)
    return out


def check(path, importer, roughness):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    importer(filepath=path)
    found = 0
    for mat in bpy.data.materials:
        if not mat.name.startswith("english-oak_"):
            continue
        nodes = mat.node_tree.nodes
        bsdf = next(n for n in nodes if n.type == "BSDF_PRINCIPLED")
        normal = bsdf.inputs["Normal"]
        assert normal.is_linked, f"{path}: {mat.name}: nothing on the BSDF's Normal"
        nm = normal.links[0].from_node
        assert nm.type == "NORMAL_MAP", f"{path}: {mat.name}: Normal fed by {nm.type}"
        images = upstream_images(nm)
        assert images, f"{path}: {mat.name}: the Normal Map node has no image"
        # The map is data, not colour: the glTF importer marks it Non-Color. Blender 3.4's OBJ
        # importer leaves map_Bump images sRGB (its choice, not the file's: the user switches
        # it), so that is only reported.
        space = images[0].colorspace_settings.name
        if path.endswith(".glb"):
            assert space == "Non-Color", f"{path}: {mat.name}: normal map read as {space}"
        elif space != "Non-Color":
            print(f"note: {os.path.basename(path)}: Blender reads the normal map as {space}")
        # Blender links an FBX's textures by file name and does not resolve Assimp's embedded
        # "*N" names (the base colour neither): the FBX is checked for the node wiring only.
        if not path.endswith(".fbx"):
            assert images[0].size[0] > 1, f"{path}: {mat.name}: the normal map did not load"
        if roughness:
            assert bsdf.inputs["Roughness"].is_linked, f"{path}: {mat.name}: no roughness map"
        found += 1
    assert found == 2, f"{path}: {found} oak materials with normal maps, expected 2"
    print(f"ok: {os.path.basename(path)}: bark and leaf normal maps"
          + (" and roughness" if roughness else ""))


def obj_import(filepath):
    try:
        bpy.ops.wm.obj_import(filepath=filepath)
    except AttributeError:
        bpy.ops.import_scene.obj(filepath=filepath)


for name, importer, roughness in (("oak.obj", obj_import, True),
                                  ("oak.glb", bpy.ops.import_scene.gltf, True),
                                  ("oak.fbx", bpy.ops.import_scene.fbx, False)):
    out = os.path.join(work, name)
    subprocess.run([cli, "tree", species, "-o", out, "--seed", "2"], check=True)
    check(out, importer, roughness)
