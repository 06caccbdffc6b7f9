"""The Blender add-on's leaf tints, headless: blender -b --factory-startup --python
test_addon_tint.py -- <add-on folder> <presets folder>. "Grow tree at cursor" with the library
oak gives a mesh whose colour attribute (build.TINT_ATTRIBUTE) holds the leaf cards' tints
(white on bark, varied on leaves, each card one colour as sylva.Mesh.colors has it) and a leaf
material that multiplies its texture by that attribute before the Principled BSDF."""
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean
import bpy  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addonsession import start_addon  # noqa: E402

sylva_blender, presets = start_addon()
from sylva_blender import build  # noqa: E402
scene = bpy.context.scene
s = scene.sylva
s.tree_file = os.path.join(presets, "english-oak.json")
s.seed = 1
assert bpy.ops.sylva.grow_tree() == {"FINISHED"}
trees = [o for o in bpy.data.objects if o.type == "MESH"]
assert len(trees) == 1, trees
me = trees[0].data
attr = me.color_attributes.get(build.TINT_ATTRIBUTE)
assert attr is not None, [a.name for a in me.color_attributes]
colors = np.zeros(len(attr.data) * 4, dtype=np.float32)
attr.data.foreach_get("color", colors)
colors = colors.reshape(-1, 4)[:, :3]
white = np.all(colors > 0.995, axis=1)
leaf = colors[~white]
print(f"addon tint: {len(colors)} vertices, {int(white.sum())} white, {len(leaf)} tinted, "
      f"green from {leaf[:, 1].min():.3f} to {leaf[:, 1].max():.3f}, "
      f"std {leaf.std(axis=0).round(3).tolist()}")
assert 0 < len(leaf) < len(colors), "bark white, leaves tinted"
assert leaf.std(axis=0).max() > 0.02, "the cards differ"
assert leaf[:, 1].min() > 0.2, "no card is near black"

mat = next(m for m in me.materials if m.name.startswith("Sylva Leaf"))
bsdf = next(n for n in mat.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
base = bsdf.inputs["Base Color"]
assert base.is_linked, "nothing on the leaf's Base Color"
mix = base.links[0].from_node
assert mix.type == "MIX_RGB" and mix.blend_type == "MULTIPLY", (mix.type, mix.blend_type)
sources = {link.from_node.type: link.from_node for i in mix.inputs for link in i.links}
assert "TEX_IMAGE" in sources and "VERTEX_COLOR" in sources, list(sources)
assert sources["VERTEX_COLOR"].layer_name == build.TINT_ATTRIBUTE
print("addon tint: ok")
