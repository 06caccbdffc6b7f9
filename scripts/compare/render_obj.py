"""Renders an OBJ (+MTL, textures) to PNG in Blender, the same camera and light for every tree,
so that trees of different generators can be compared side by side (docs/gallery.md).

  blender -b --factory-startup --python scripts/compare/render_obj.py -- tree.obj out.png [size]
"""
import math
import sys

import bpy
from mathutils import Vector

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, out_path = argv[0], argv[1]
size = int(argv[2]) if len(argv) > 2 else 480

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="NEGATIVE_Z", up_axis="Y")
objs = [o for o in bpy.context.scene.objects if o.type == "MESH"]
for o in objs:
    for slot in o.material_slots:
        m = slot.material
        if not m or not m.use_nodes:
            continue
        nodes, links = m.node_tree.nodes, m.node_tree.links
        bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
        tex = next((n for n in nodes if n.type == "TEX_IMAGE"), None)
        if bsdf:
            bsdf.inputs["Specular"].default_value = 0.1
            bsdf.inputs["Roughness"].default_value = 0.8
        # Bark vertex colours (Sylva's Scots pine: grey low, orange high) multiply the texture
        # that feeds the base colour, as glTF and USD readers do.
        base = next((l.from_node for l in links if bsdf and l.to_node == bsdf
                     and l.to_socket.name == "Base Color" and l.from_node.type == "TEX_IMAGE"),
                    None)
        if base and "bark" in m.name.lower() and o.data.color_attributes:
            attr = nodes.new("ShaderNodeVertexColor")
            attr.layer_name = o.data.color_attributes[0].name
            mix = nodes.new("ShaderNodeMix")
            mix.data_type = "RGBA"
            mix.blend_type = "MULTIPLY"
            mix.inputs["Factor"].default_value = 1.0
            links.new(base.outputs["Color"], mix.inputs[6])
            links.new(attr.outputs["Color"], mix.inputs[7])
            links.new(mix.outputs[2], bsdf.inputs["Base Color"])
        if bsdf and tex and "leaf" in m.name.lower():
            links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
            m.blend_method = "CLIP"
            m.shadow_method = "CLIP"
            m.use_backface_culling = False

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
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 3.5
sun.rotation_euler = (math.radians(50), 0, math.radians(-35))
bpy.context.scene.collection.objects.link(sun)
world = bpy.data.worlds.new("sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.55, 0.65, 0.8, 1)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.8
bpy.context.scene.world = world
scene = bpy.context.scene
scene.render.engine = "BLENDER_EEVEE"
scene.eevee.taa_render_samples = 16
scene.render.resolution_x = scene.render.resolution_y = size
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
