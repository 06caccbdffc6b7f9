"""Renders a close view of an OBJ tree (a trunk's base, a crown's joint) in Blender, camera at
an eye point looking at a target, both in the tree's own frame (metres, y up), over a ground,
under the same sun and sky as scripts/compare/render_obj.py (docs/species.md's close-ups).

  blender -b --factory-startup --python scripts/render_closeup.py -- tree.obj out.png \\
      EX,EY,EZ TX,TY,TZ [width height] [--lens MM]
"""
import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare"))
import blenderlook  # noqa: E402  (the look every comparison render shares)

argv = sys.argv[sys.argv.index("--") + 1:]
lens = 35.0
if "--lens" in argv:
    i = argv.index("--lens")
    lens = float(argv[i + 1])
    del argv[i:i + 2]
obj_path, out_path = argv[0], argv[1]


def blender_point(text):
    # The OBJ is imported with y up and -z forward: (x, y, z) -> (x, -z, y).
    x, y, z = (float(v) for v in text.split(","))
    return Vector((x, -z, y))


eye, target = blender_point(argv[2]), blender_point(argv[3])
width = int(argv[4]) if len(argv) > 4 else 640
height = int(argv[5]) if len(argv) > 5 else 480

blenderlook.import_obj(obj_path)

# Ground: a large plane at y = 0, grass-brown.
bpy.ops.mesh.primitive_plane_add(size=200, location=(0, 0, 0))
ground = bpy.context.active_object
mat = bpy.data.materials.new("ground")
mat.use_nodes = True
mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.23, 0.25, 0.13, 1)
mat.node_tree.nodes["Principled BSDF"].inputs["Roughness"].default_value = 0.95
ground.data.materials.append(mat)

cam_data = bpy.data.cameras.new("cam")
cam_data.lens = lens
cam = bpy.data.objects.new("cam", cam_data)
bpy.context.scene.collection.objects.link(cam)
cam.location = eye
cam.rotation_euler = (target - eye).to_track_quat("-Z", "Y").to_euler()
bpy.context.scene.camera = cam
blenderlook.light_and_render(out_path, width, height, soft_shadows=True)
