"""The Blender add-on with wind, headless: blender -b --factory-startup --python
test_addon_wind.py -- <add-on folder> <presets folder>. "Grow tree at cursor" with Wind on gives
an armature with the "wind" action and the tree's mesh skinned to it; the action plays (a vertex
moves between two frames) and the tree stands at the cursor. A small tree, 8 bones, a 1 s clip."""
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean
import bpy  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addonsession import start_addon  # noqa: E402

sylva_blender, presets = start_addon()
scene = bpy.context.scene
scene.cursor.location = (3.0, -2.0, 0.0)
s = scene.sylva
s.tree_file = os.path.join(presets, "ternary-tree.json")
s.seed = 3
s.wind = True
s.wind_strength = 1.5
s.wind_bones = 8
s.wind_clip = 1.0
assert bpy.ops.sylva.grow_tree() == {"FINISHED"}

armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
skinned = [o for o in bpy.data.objects if o.type == "MESH" and o.find_armature()]
assert len(armatures) == 1 and len(skinned) == 1, (armatures, skinned)
armature, mesh = armatures[0], skinned[0]
action = armature.animation_data.action
assert action and action.name.startswith("wind"), action
assert 2 <= len(armature.data.bones) <= 8, len(armature.data.bones)
first, last = int(action.frame_range[0]), int(action.frame_range[1])
# 1 s: the importer places the keys at the scene's frame rate (24 fps by default).
assert last - first == round(scene.render.fps / scene.render.fps_base), (first, last)
assert scene.frame_end >= last


def positions():
    evaluated = mesh.evaluated_get(bpy.context.evaluated_depsgraph_get())
    m = evaluated.to_mesh()
    co = np.empty(len(m.vertices) * 3)
    m.vertices.foreach_get("co", co)
    evaluated.to_mesh_clear()
    w = np.array(mesh.matrix_world)
    return co.reshape(-1, 3) @ w[:3, :3].T + w[:3, 3]


scene.frame_set(first)
a = positions()
scene.frame_set(first + 8)
b = positions()
moved = float(np.linalg.norm(a - b, axis=1).max())
base = a[np.argmin(a[:, 2])]
print(f"addon wind: {len(armature.data.bones)} bones, {len(a)} vertices, "
      f"largest move between frames {first} and {first + 8}: {moved:.4f} m, base at {base}")
assert moved > 1e-3, moved  # the action plays
assert abs(base[0] - 3.0) < 0.5 and abs(base[1] + 2.0) < 0.5 and abs(base[2]) < 0.2, base
scene.frame_set(last)
assert float(np.linalg.norm(positions() - a, axis=1).max()) < 1e-3  # the clip loops

# The forest with Wind: every tree an armature with its "wind" action, the trees of a variant
# sharing one mesh datablock, and the action plays.
from sylva_blender import build  # noqa: E402

bpy.ops.mesh.primitive_plane_add(size=30, location=(0, 0, 0))
s.ground = bpy.context.active_object
item = s.species.add()
item.file = os.path.join(presets, "ternary-tree.json")
item.count = 12
s.lod = False  # instanced trees show their variant's mesh
forest = build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
col = bpy.data.collections[build.FOREST_COLLECTION]
arms = [o for o in col.objects if o.type == "ARMATURE"]
drawn = [t for t in forest.trees if len(t.mesh.positions)]
assert len(arms) == len(drawn) > 1, (len(arms), len(drawn))
assert all(a.animation_data and a.animation_data.action
           and "wind" in a.animation_data.action.name for a in arms)
assert all(len(a.data.bones) <= 8 for a in arms)
skinned = {o.name[:-len("_mesh")]: o for o in col.objects
           if o.type == "MESH" and o.find_armature()}
assert len(skinned) == len(drawn), (len(skinned), len(drawn))
by_variant = {}
for t in drawn:
    if t.instanced:
        by_variant.setdefault(t.variant, set()).add(skinned[t.name].data.name)
assert by_variant and any(len([t for t in drawn if t.variant == v]) > 1 for v in by_variant)
assert all(len(names) == 1 for names in by_variant.values()), by_variant  # one mesh a variant
meshes = {o.data for o in skinned.values()}
assert len(meshes) == len(by_variant) + sum(1 for t in drawn if not t.instanced), len(meshes)
mesh = skinned[drawn[0].name]
scene.frame_set(first)
a = positions()
scene.frame_set(first + 8)
moved = float(np.linalg.norm(positions() - a, axis=1).max())
print(f"addon wind forest: {len(arms)} armatures, {len(meshes)} meshes for {len(drawn)} trees, "
      f"largest move of {drawn[0].name} over 8 frames {moved:.4f} m")
assert moved > 1e-3, moved
# Growing it again replaces it: no armature, mesh or action left behind.
counts = (len(bpy.data.armatures), len(bpy.data.meshes), len(bpy.data.actions))
build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
assert (len(bpy.data.armatures), len(bpy.data.meshes), len(bpy.data.actions)) == counts, counts
sylva_blender.unregister()
print("PASS blender_addon_wind")
