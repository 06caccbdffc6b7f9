"""Renders an OBJ (+MTL, textures) to PNG in Blender, the same camera and light for every tree,
so that trees of different generators can be compared side by side (docs/gallery.md).

  blender -b --factory-startup --python scripts/compare/render_obj.py -- tree.obj out.png [size]
"""
import math
import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blenderlook  # noqa: E402  (the look every comparison render shares)

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, out_path = argv[0], argv[1]
size = int(argv[2]) if len(argv) > 2 else 480

objs = blenderlook.import_obj(obj_path)

lo = Vector((1e9, 1e9, 1e9))
hi = -lo
for o in objs:
    for c in o.bound_box:
        w = o.matrix_world @ Vector(c)
        lo = Vector(map(min, lo, w))
        hi = Vector(map(max, hi, w))
centre = (lo + hi) / 2
radius = (hi - lo).length / 2
cam_data = bpy.data.cameras.new("cam")
cam_data.lens = 50
cam = bpy.data.objects.new("cam", cam_data)
bpy.context.scene.collection.objects.link(cam)
d = radius / math.tan(cam_data.angle / 2) * 0.8
direction = Vector((0.0, -1.0, 0.35)).normalized()
cam.location = centre + direction * d
cam.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
bpy.context.scene.camera = cam
blenderlook.light_and_render(out_path, size, size)
