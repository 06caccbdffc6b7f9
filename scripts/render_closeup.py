"""Renders a close view of an OBJ tree (a trunk's base, a crown's joint) in Blender, camera at
an eye point looking at a target, both in the tree's own frame (metres, y up), over a ground,
under the same sun and sky as scripts/compare/render_obj.py (docs/species.md's close-ups).

  blender -b --factory-startup --python scripts/render_closeup.py -- tree.obj out.png \\
      EX,EY,EZ TX,TY,TZ [width height] [--lens MM]
"""
import math
import sys

import bpy
from mathutils import Vector

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

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="NEGATIVE_Z", up_axis="Y")
for o in [o for o in bpy.context.scene.objects if o.type == "MESH"]:
    for slot in o.material_slots:
        m = slot.material
        if not m or not m.use_nodes:
            continue
        nodes, links = m.node_tree.nodes, m.node_tree.links
        bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
        # The image that feeds the base colour (the importer also adds normal and roughness).
        tex = next((l.from_node for l in links if bsdf and l.to_node == bsdf
                    and l.to_socket.name == "Base Color" and l.from_node.type == "TEX_IMAGE"),
                   None)
        if bsdf:
            bsdf.inputs["Specular"].default_value = 0.1
            bsdf.inputs["Roughness"].default_value = 0.8
        if bsdf and tex and "leaf" in m.name.lower():
            links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
            m.blend_method = "CLIP"
            m.shadow_method = "CLIP"
            m.use_backface_culling = False
        # Vertex colours (the pine's bark blend by height) multiply the texture, as in the
        # glTF and USD readers.
        if bsdf and tex and "bark" in m.name.lower() and o.data.color_attributes:
            attr = nodes.new("ShaderNodeVertexColor")
            attr.layer_name = o.data.color_attributes[0].name
            mix = nodes.new("ShaderNodeMix")
            mix.data_type = "RGBA"
            mix.blend_type = "MULTIPLY"
            mix.inputs["Factor"].default_value = 1.0
            links.new(tex.outputs["Color"], mix.inputs[6])
            links.new(attr.outputs["Color"], mix.inputs[7])
            links.new(mix.outputs[2], bsdf.inputs["Base Color"])

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
scene.eevee.use_soft_shadows = True
scene.eevee.shadow_cascade_size = "2048"
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
