"""Blender 3.4 imports a wind GLB (docs/wind.md) with its armature and the "wind" action, and the
tip of the tallest branch moves at least 5x as far as a point on the lower trunk over the clip.
Usage: blender -b --python test_wind_glb.py -- SYLVA_CLI PRESETS WORK"""
import os
import subprocess
import sys

import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still uses the removed alias
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

cli, presets, work = sys.argv[sys.argv.index("--") + 1:][:3]
os.makedirs(work, exist_ok=True)
glb = os.path.join(work, "oak_wind.glb")
subprocess.run([cli, "tree", os.path.join(presets, "english-oak.json"), "--seed", "2", "-o", glb,
                "--wind"], check=True)
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
skinned = [o for o in bpy.data.objects if o.type == "MESH" and o.find_armature()]
assert len(armatures) == 1 and len(skinned) == 1, (armatures, skinned)
action = armatures[0].animation_data.action
assert action and action.name.startswith("wind"), action
assert 2 <= len(armatures[0].data.bones) <= 64, len(armatures[0].data.bones)
mesh = skinned[0]
scene = bpy.context.scene


def positions():
    evaluated = mesh.evaluated_get(bpy.context.evaluated_depsgraph_get())
    m = evaluated.to_mesh()
    out = [mesh.matrix_world @ v.co for v in m.vertices]
    evaluated.to_mesh_clear()
    return out


first, last = int(action.frame_range[0]), int(action.frame_range[1])
scene.frame_set(first)
rest = positions()
zs = [v.z for v in rest]
height = max(zs) - min(zs)
tip = max(range(len(rest)), key=lambda i: rest[i].z)
# A point on the lower trunk: the vertex nearest the axis at a tenth of the height.
low = min(range(len(rest)),
          key=lambda i: abs(rest[i].z - min(zs) - 0.1 * height) + Vector(rest[i].xy).length)
tip_moved = low_moved = 0.0
for frame in range(first, last + 1, 6):
    scene.frame_set(frame)
    p = positions()
    tip_moved = max(tip_moved, (p[tip] - rest[tip]).length)
    low_moved = max(low_moved, (p[low] - rest[low]).length)
scene.frame_set(last)
loop = max((a - b).length for a, b in zip(positions(), rest))
print(f"wind: frames {first}..{last}, tip {tip_moved:.3f} m, lower trunk {low_moved:.4f} m, "
      f"first/last frame apart {loop:.2e} m")
assert tip_moved > 0.05, tip_moved
assert tip_moved >= 5 * low_moved, (tip_moved, low_moved)
assert loop < 1e-3, loop
print("PASS blender_wind_glb")
