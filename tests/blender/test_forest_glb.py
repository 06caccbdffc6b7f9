# Blender 3.4 imports Sylva's instanced forest GLB (run by ctest: blender -b --python this --
# <sylva-cli> <tests/data> <scratch>). Its importer predates EXT_mesh_gpu_instancing, which the
# file uses without requiring it: Blender shows each cell's variant once (at its first instance)
# plus every unique tree, and keeps the tree ids (glTF extras) as custom properties.
import json
import os
import struct
import subprocess
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 glTF importer uses np.bool, which its numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

cli, data, work = sys.argv[sys.argv.index("--") + 1:][:3]
os.makedirs(work, exist_ok=True)
path = os.path.join(work, "forest.glb")
subprocess.run([cli, "forest", os.path.join(data, "projects", "small.sylva"), "-o", path],
               check=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)

raw = open(path, "rb").read()
doc = json.loads(raw[20:20 + struct.unpack("<I", raw[12:16])[0]])
nodes_with_mesh = sum(1 for n in doc["nodes"] if "mesh" in n)
instanced_ids = sum(len(n.get("extras", {}).get("sylva_ids", [])) for n in doc["nodes"])
unique_ids = sum(1 for n in doc["nodes"] if "sylva_id" in n.get("extras", {}))

meshes = [o for o in bpy.data.objects if o.type == "MESH"]
got_ids = sum(len(o.get("sylva_ids", [])) for o in bpy.data.objects)
got_unique = sum(1 for o in bpy.data.objects if "sylva_id" in o)
print(f"blender: {len(meshes)} mesh objects, {got_ids} instance ids, {got_unique} unique trees")
assert len(meshes) == nodes_with_mesh, (len(meshes), nodes_with_mesh)
assert got_ids == instanced_ids > 0, (got_ids, instanced_ids)
assert got_unique == unique_ids, (got_unique, unique_ids)
assert len(bpy.data.images) == len(doc.get("images", [])) > 0, "embedded textures not imported"
# The cells are empties holding their trees: an artist can hide a cell at a time.
cells = [o for o in bpy.data.objects if o.name.startswith("cell_")]
assert len(cells) == sum(1 for n in doc["nodes"] if n.get("name", "").startswith("cell_"))
print("PASS blender_forest_glb")
