"""The Blender add-on imports a Sylva project with its branch edits (issue 43), headless:
blender -b --factory-startup --python test_addon_project.py -- <add-on folder> <presets folder>
<work folder>. An English oak (seed 11) is saved as grown and with limb 0.5 pruned and limb 0.2
bent; "Import project" (the panel's button) builds each: the edited one has fewer vertices, its
vertices are those of the sylva module's build of the same file, and importing again after the
project changed (the tree's season) keeps the edits. Exits 1 on failure (--python-exit-code 1)."""
import os
import sys

sys.dont_write_bytecode = True  # keep the source tree clean
import bpy
import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:]
addon_dir, presets_dir, work = argv[0], argv[1], argv[2]
os.makedirs(work, exist_ok=True)
sys.path.insert(0, addon_dir)
import sylva_blender  # noqa: E402
from sylva_blender import build  # noqa: E402

sylva_blender.register()
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)
sylva = sylva_blender.import_sylva()

plain = os.path.join(work, "oak.sylva")
edited = os.path.join(work, "oak-edited.sylva")
autumn = os.path.join(work, "oak-edited-autumn.sylva")
project = sylva.Project(seed=1)
project.add_species("english-oak", os.path.join(presets_dir, "english-oak.json"))
tree = project.add_tree("english-oak", (0.0, 0.0, 0.0), seed=11)
project.save(plain)
project.edit_branch(tree, "0.5", prune=True)
project.edit_branch(tree, "0.2", bend=(-0.3, 1.0, 0.0))
project.save(edited)
project.set_tree_season(tree, "autumn")
project.save(autumn)

s = bpy.context.scene.sylva
s.lod = False


def imported(path):
    """Imports \\p path through the operator; returns the one tree object's vertices (world
    space, Blender axes) and its bark triangle count."""
    s.project_file = path
    assert bpy.ops.sylva.import_project() == {"FINISHED"}, path
    objs = list(bpy.data.collections[build.PROJECT_COLLECTION].objects)
    assert len(objs) == 1, f"{path}: {len(objs)} objects (the last import was not replaced)"
    obj = objs[0]
    assert obj["sylva_project"] == path and obj["sylva_id"] == str(tree), dict(obj)
    n = len(obj.data.vertices)
    co = np.empty(n * 3)
    obj.data.vertices.foreach_get("co", co)
    m = np.array(obj.matrix_world)
    world = co.reshape(n, 3) @ m[:3, :3].T + m[:3, 3]
    bark_slot = [k for k, mat in enumerate(obj.data.materials) if mat.name.startswith("Sylva Bark")]
    mats = np.empty(len(obj.data.polygons), dtype=np.int32)
    obj.data.polygons.foreach_get("material_index", mats)
    return world, int(np.isin(mats, bark_slot).sum())


grown, grown_bark = imported(plain)
cut, cut_bark = imported(edited)
print(f"as grown: {len(grown)} vertices, {grown_bark} bark triangles; edited: {len(cut)} "
      f"vertices, {cut_bark} bark triangles")
assert cut_bark < grown_bark, "the pruned limb's bark is still there"
assert len(cut) < len(grown)

# The import is the engine's build of the file, edits and all (same vertices, same order).
reference = sylva.load_project(edited)
assert len(reference.branch_edits(tree)) == 2, reference.branch_edits(tree)
forest = reference.build_forest(lod=False, adapt=s.adapt, instancing=s.instancing)
assert forest.stats["branch_edits"] == 2 and forest.stats["orphaned_edits"] == 0, forest.stats
mesh = forest.trees[0].mesh
expected = build.to_blender(mesh.positions)
assert expected.shape == cut.shape, (expected.shape, cut.shape)
diff = float(np.abs(expected - cut).max())
assert diff < 1e-4, f"the imported tree is not the edited one: {diff} m apart"

# The bend moved limb 0.2 (not only the prune): the module's tree with the bend alone has its
# vertices' centre elsewhere than the tree as grown (its leaf clusters may differ in number).
only_bent = sylva.load_project(plain)
only_bent.edit_branch(tree, "0.2", bend=(-0.3, 1.0, 0.0))
bent = only_bent.build_forest(lod=False, adapt=s.adapt, instancing=s.instancing).trees[0].mesh
moved = float(np.linalg.norm(build.to_blender(bent.positions).mean(axis=0) - grown.mean(axis=0)))
assert moved > 0.05, f"the bend moved the tree's centre by {moved} m"

# The project changed (the tree's season) and imported again: the edits are still applied.
fall, fall_bark = imported(autumn)
assert fall_bark == cut_bark, (fall_bark, cut_bark)
# A missing project file: the button reports it and cancels; the last import stays.
s.project_file = os.path.join(os.path.dirname(autumn), "missing.sylva")
try:
    result = bpy.ops.sylva.import_project()
except RuntimeError as e:  # an operator's ERROR report, raised in background mode
    assert "missing.sylva" in str(e), e
    result = {"CANCELLED"}
assert result == {"CANCELLED"}, result
assert len(bpy.data.collections[build.PROJECT_COLLECTION].objects) == 1
print(f"regrown in autumn: {fall_bark} bark triangles, as edited; the bend moved the centre "
      f"{moved:.2f} m; the import matches the module's build within {diff:.1e} m")
print("OK")
