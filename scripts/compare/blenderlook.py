"""The look every Blender render of a Sylva or ez-tree OBJ shares (scripts/compare/render_obj.py
for the gallery's comparison, scripts/render_closeup.py for the close-ups): the import with y up,
the materials as the glTF and USD readers show them, one sun and one sky, EEVEE."""
import math

import bpy


def import_obj(obj_path):
    """Empties the scene, imports \\p obj_path (y up, -z forward) and sets its materials: little
    specular, leaves alpha-clipped and two-sided, bark vertex colours (the Scots pine's grey low,
    orange high) multiplying the texture that feeds the base colour. Returns the mesh objects."""
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
            if not bsdf:
                continue
            bsdf.inputs["Specular"].default_value = 0.1
            bsdf.inputs["Roughness"].default_value = 0.8
            # The image that feeds the base colour (the importer also adds normal and roughness).
            tex = next((l.from_node for l in links if l.to_node == bsdf
                        and l.to_socket.name == "Base Color" and l.from_node.type == "TEX_IMAGE"),
                       None)
            if not tex:
                continue
            if "leaf" in m.name.lower():
                links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
                m.blend_method = "CLIP"
                m.shadow_method = "CLIP"
                m.use_backface_culling = False
            if "bark" in m.name.lower() and o.data.color_attributes:
                attr = nodes.new("ShaderNodeVertexColor")
                attr.layer_name = o.data.color_attributes[0].name
                mix = nodes.new("ShaderNodeMix")
                mix.data_type = "RGBA"
                mix.blend_type = "MULTIPLY"
                mix.inputs["Factor"].default_value = 1.0
                links.new(tex.outputs["Color"], mix.inputs[6])
                links.new(attr.outputs["Color"], mix.inputs[7])
                links.new(mix.outputs[2], bsdf.inputs["Base Color"])
    return objs


def light_and_render(out_path, width, height, soft_shadows=False):
    """The sun and sky of every comparison picture, then an EEVEE render to \\p out_path."""
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
    if soft_shadows:
        scene.eevee.use_soft_shadows = True
        scene.eevee.shadow_cascade_size = "2048"
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.filepath = out_path
    bpy.ops.render.render(write_still=True)
