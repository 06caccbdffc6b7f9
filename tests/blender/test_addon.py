"""The Blender add-on, headless: blender -b --factory-startup --python test_addon.py --
<add-on folder> <test data folder>. A plane is the ground, a cube the obstacle; the forest grown
over the plane has no tree vertex inside the cube, before and after the cube moves. Exits 1 on
failure (--python-exit-code 1).

"Inside" means inside by more than float rounding (1 µm): placement keeps a trunk its bark
radius away from an obstacle's footprint, and adaptation tests each branch as a tube of its bark
radius, so no bark (and no leaf card) ends inside the cube."""
import os
import sys
import time

sys.dont_write_bytecode = True  # keep the source tree clean
import bpy
import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:]
addon_dir, data_dir = argv[0], argv[1]
sys.path.insert(0, addon_dir)
import sylva_blender  # noqa: E402
from sylva_blender import build  # noqa: E402

start = time.perf_counter()
TOLERANCE = 1e-6  # metres: float rounding of the world transform, see above
sylva_blender.register()
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
scene = bpy.context.scene

bpy.ops.mesh.primitive_plane_add(size=24, location=(0, 0, 0))
ground = bpy.context.active_object
ground.name = "Ground"
obstacles = bpy.data.collections.new("Obstacles")
scene.collection.children.link(obstacles)
bpy.ops.mesh.primitive_cube_add(size=4, location=(0, 0, 2))
cube = bpy.context.active_object
cube.name = "Cube"
for c in list(cube.users_collection):
    c.objects.unlink(cube)
obstacles.objects.link(cube)

s = scene.sylva
item = s.species.add()
item.file = os.path.join(data_dir, "lsystem", "bush.lsys")
item.count = 40
s.ground = ground
s.obstacles = obstacles
s.seed = 11  # a forest where 99 tree vertices end inside the cube unless adapted


def check(label):
    bpy.context.view_layer.update()
    col = bpy.data.collections[build.FOREST_COLLECTION]
    trees = list(col.objects)
    assert len(trees) == 40, f"{label}: {len(trees)} tree objects"
    lo = np.array(cube.matrix_world.translation) - 2.0
    hi = np.array(cube.matrix_world.translation) + 2.0
    inside = 0
    total = 0
    shapes = {}
    for obj in trees:
        n = len(obj.data.vertices)
        co = np.empty(n * 3)
        obj.data.vertices.foreach_get("co", co)
        m = np.array(obj.matrix_world)
        world = co.reshape(n, 3) @ m[:3, :3].T + m[:3, 3]
        shapes[obj.name] = round(float(np.abs(co).sum()), 3)
        inside += int(np.sum(np.all((world > lo + TOLERANCE) & (world < hi - TOLERANCE), axis=1)))
        total += n
        assert obj.data.materials[0].name.startswith("Sylva"), obj.data.materials[:]
        assert abs(world[:, 2].min()) < 0.5, f"{obj.name} does not stand on the ground"
    assert inside == 0, f"{label}: {inside} of {total} tree vertices inside the cube"
    print(f"{label}: {len(trees)} trees, {total} vertices, none inside the cube")
    # Where the trees stand and what shape they have (adaptation bends and prunes them).
    return {o.name: (tuple(o.location), len(o.data.vertices), shapes[o.name]) for o in trees}


# The forest, grown through the operator the panel's button runs.
assert bpy.ops.sylva.grow_forest() == {"FINISHED"}
first = check("forest")
# It met the cube: with adaptation off some vertices would be inside.
forest = build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
assert forest.stats["colliding_trees"] > 0, forest.stats
s.adapt = False
build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
try:
    check("not adapted")
    raise SystemExit("without adaptation no vertex was inside the cube: the test proves nothing")
except AssertionError as e:
    print("without adaptation:", e)
s.adapt = True

# Other forests (seeds) over the same scene: none has a vertex inside the cube either.
for seed in range(1, 9):
    s.seed = seed
    build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
    check(f"seed {seed}")
s.seed = 11

# Move the obstacle and regrow: the trees avoid it where it is now.
cube.location = (5, 4, 2)
assert bpy.ops.sylva.grow_forest() == {"FINISHED"}
second = check("after moving the cube")
assert first != second, "the forest did not change when the obstacle moved"

# With "regrow when an obstacle changes", moving the cube schedules a regrow (a timer, which
# background mode does not run: the test runs it).
s.auto_regrow = True
cube.location = (-5, -4, 2)
bpy.context.view_layer.update()
assert sylva_blender.regrow_pending(), "moving the obstacle scheduled no regrow"
sylva_blender.regrow_now()
third = check("regrown after the cube moved again")
assert third != second

# Instanced trees are linked duplicates: one mesh datablock per variant, shared by every tree
# that shows it; unique trees (near the cube or a neighbour) have their own.
forest = build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
objs = list(bpy.data.collections[build.FOREST_COLLECTION].objects)
st = forest.stats
assert st["instanced"] > 0 and st["unique"] > 0 and st["instanced"] + st["unique"] == 40, st
by_variant = {}
for o in objs:
    if o["sylva_variant"]:
        by_variant.setdefault(o["sylva_variant"], set()).add(o.data.name)
    else:
        assert o.data.users == 1, f"{o.name}: a unique tree shares its mesh"
assert all(len(names) == 1 for names in by_variant.values()), by_variant
shared = [o for o in objs if o["sylva_variant"] and o.data.users > 1]
assert shared, "no two trees share a variant's mesh"
meshes = {o.data.name for o in objs}
assert len(meshes) == st["unique"] + len(by_variant), (len(meshes), st, len(by_variant))
assert len({o["sylva_id"] for o in objs}) == 40, "tree ids repeat"
print(f"instancing: {st['instanced']} instanced trees share {len(by_variant)} meshes, "
      f"{st['unique']} unique; {len(meshes)} meshes for 40 trees")
s.instancing = False
build.grow_forest(sylva_blender.import_sylva(), bpy.context, s)
objs = list(bpy.data.collections[build.FOREST_COLLECTION].objects)
assert len({o.data.name for o in objs}) == 40 and all(o.data.users == 1 for o in objs)
s.instancing = True

# One tree at the 3D cursor.
scene.cursor.location = (30, 0, 0)
s.tree_file = os.path.join(data_dir, "lsystem", "bush.lsys")
assert bpy.ops.sylva.grow_tree() == {"FINISHED"}
tree = bpy.context.scene.collection.objects[-1]
assert tuple(tree.location) == (30, 0, 0), tuple(tree.location)
assert len(tree.data.vertices) > 0 and len(tree.data.uv_layers) == 1
bark = bpy.data.materials["Sylva Bark"]
assert any(n.type == "TEX_IMAGE" and n.image for n in bark.node_tree.nodes), "bark texture"
print(f"blender add-on test passed in {time.perf_counter() - start:.1f} s")
