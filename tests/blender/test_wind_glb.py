"""Blender 3.4 imports a wind GLB (docs/wind.md) with its armature and the "wind" action, and the
tip of the tallest branch moves at least 5x as far as a point on the lower trunk over the clip.
Usage: blender -b --python test_wind_glb.py -- SYLVA_CLI PRESETS WORK"""
import os
import subprocess
import sys

import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still uses the removed alias
import bpy  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from windmotion import assert_sways, measure_motion  # noqa: E402

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
first, last = int(action.frame_range[0]), int(action.frame_range[1])
height, tip_moved, low_moved, loop = measure_motion(skinned, first, last)
print(f"wind: frames {first}..{last}, tip {tip_moved:.3f} m, lower trunk {low_moved:.4f} m, "
      f"first/last frame apart {loop:.2e} m")
assert_sways(tip_moved, low_moved, loop)
print("PASS blender_wind_glb")
