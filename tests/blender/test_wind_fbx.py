"""Blender 3.4 imports a wind FBX (docs/wind.md) with one armature (every joint a bone) and the
"wind" action at the clip's frame rate; the tip of the tallest branch moves at least 5x as far as
a point on the lower trunk over the clip, and the clip loops.
Usage: blender -b --python test_wind_fbx.py -- SYLVA_CLI PRESETS WORK"""
import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from windmotion import assert_sways, measure_motion  # noqa: E402

cli, presets, work = sys.argv[sys.argv.index("--") + 1:][:3]
os.makedirs(work, exist_ok=True)
fbx = os.path.join(work, "oak_wind.fbx")
subprocess.run([cli, "tree", os.path.join(presets, "english-oak.json"), "--seed", "2", "-o", fbx,
                "--wind", "--bones", "64"], check=True)
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.fbx(filepath=fbx)  # before the fix: KeyError 'armature_setup'
armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
skinned = [o for o in bpy.data.objects if o.type == "MESH" and o.find_armature()]
assert len(armatures) == 1 and len(skinned) == 2, (armatures, skinned)  # bark and leaves
arm = armatures[0]
assert len(arm.data.bones) == 64, len(arm.data.bones)
action = arm.animation_data.action
assert action and "wind" in action.name, action
scene = bpy.context.scene
assert scene.render.fps == 30, scene.render.fps  # the file's custom frame rate
first, last = int(action.frame_range[0]), int(action.frame_range[1])
assert last - first == 120, (first, last)  # 4 s at 30 fps


height, tip_moved, low_moved, loop = measure_motion(skinned, first, last)
print(f"wind fbx: {len(arm.data.bones)} bones, frames {first}..{last}, height {height:.2f} m, "
      f"tip {tip_moved:.3f} m, lower trunk {low_moved:.4f} m, first/last apart {loop:.2e} m")
assert_sways(tip_moved, low_moved, loop)

# A forest: every tree its own armature with the action and its skinned mesh (a tree whose mesh
# was the Model above its bones lost half the forest to Blender's parenting before).
forest_fbx = os.path.join(work, "forest_wind.fbx")
project = os.path.join(presets, "..", "tests", "data", "projects", "small.sylva")
subprocess.run([cli, "forest", project, "-o", forest_fbx, "--wind", "--bones", "8",
                "--clip-length", "1"], check=True)
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.fbx(filepath=forest_fbx)
armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
skinned = [o for o in bpy.data.objects if o.type == "MESH" and o.find_armature()]
animated = [a for a in armatures if a.animation_data and a.animation_data.action]
# The trees with a mesh: the objects of the wind table written beside the FBX.
with open(os.path.join(work, "forest_wind.wind.csv")) as table:
    next(table)
    trees = len({line.split(",", 1)[0] for line in table})
print(f"wind fbx forest: {trees} trees, {len(armatures)} armatures, {len(skinned)} skinned meshes, "
      f"{len(animated)} with an action")
assert len(armatures) == len(animated) == len(skinned) == trees > 1, (
    len(armatures), len(animated), len(skinned), trees)
print("PASS blender_wind_fbx")
