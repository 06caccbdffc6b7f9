"""Sylva for Blender: grow trees and forests with Sylva's engine around Blender's own meshes.

The add-on calls the `sylva` Python module (Debian's python3 3.11 is Blender 3.4's Python, so
the same module loads here). It finds the module on sys.path, in $SYLVA_PYTHONPATH, or beside an
installed Sylva (<prefix>/lib/python3/dist-packages). See docs/python.md.
"""

bl_info = {
    "name": "Sylva trees and forests",
    "author": "Sylva",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > Sylva",
    "description": "Grow procedural trees and forests that bend away from your meshes",
    "category": "Add Mesh",
}

import os
import sys

import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty,
                       FloatVectorProperty, IntProperty, PointerProperty, StringProperty)

from . import build

FOREST_COLLECTION = "Sylva Forest"


def import_sylva():
    """The sylva module, looked for on sys.path, then in $SYLVA_PYTHONPATH and beside an
    installed Sylva. Raises ImportError with what was tried."""
    try:
        import sylva
        return sylva
    except ImportError:
        pass
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [p for p in os.environ.get("SYLVA_PYTHONPATH", "").split(os.pathsep) if p]
    # <prefix>/share/sylva/blender/sylva_blender → <prefix>/lib/python3/dist-packages
    candidates.append(os.path.normpath(os.path.join(here, "../../../../lib/python3/dist-packages")))
    for path in candidates:
        if os.path.isdir(path) and path not in sys.path:
            sys.path.append(path)
    try:
        import sylva
        return sylva
    except ImportError as e:
        raise ImportError("the sylva Python module was not found (tried sys.path and "
                          + ", ".join(candidates) + "): " + str(e)) from e


def preset_items(self, context):
    try:
        sylva = import_sylva()
        folder = sylva.presets_dir()
    except ImportError:
        return [("", "(sylva module not found)", "")]
    items = []
    for name in sorted(os.listdir(folder)) if folder else []:
        if name.endswith(".json"):
            items.append((os.path.join(folder, name), name[:-5], "preset " + name))
    # Enum items must stay referenced while Blender shows them.
    preset_items.cache = items or [("", "(no presets)", "")]
    return preset_items.cache


class SylvaSpeciesCount(bpy.types.PropertyGroup):
    preset: EnumProperty(name="Species", items=preset_items,
                         description="A shipped species preset")
    file: StringProperty(name="File", subtype="FILE_PATH",
                         description="A species file or grammar instead of the preset")
    count: IntProperty(name="Trees", default=10, min=0, max=100000)

    def species_path(self):
        return bpy.path.abspath(self.file) if self.file else self.preset


class SylvaSettings(bpy.types.PropertyGroup):
    species: CollectionProperty(type=SylvaSpeciesCount)
    active: IntProperty(default=0)
    seed: IntProperty(name="Seed", default=1, min=0)
    ground: PointerProperty(name="Ground", type=bpy.types.Object,
                            poll=lambda self, o: o.type == "MESH",
                            description="Trees stand on this mesh, over its footprint")
    obstacles: PointerProperty(name="Obstacles", type=bpy.types.Collection,
                               description="Meshes the trees bend away from")
    adapt: BoolProperty(name="Adapt to obstacles", default=True)
    lod: BoolProperty(name="Level of detail from the camera", default=False)
    instancing: BoolProperty(name="Share variants", default=True,
                             description="Trees that touch no obstacle and no neighbour show one "
                                         "of their species' 8 variants: linked duplicates of one "
                                         "mesh per variant (without the camera's level of detail)")
    auto_regrow: BoolProperty(name="Regrow when the ground or an obstacle changes",
                              default=False,
                              description="Grow the forest again shortly after the ground or "
                                          "an obstacle is moved or edited")
    tree_preset: EnumProperty(name="Tree", items=preset_items)
    tree_file: StringProperty(name="File", subtype="FILE_PATH")
    wind: BoolProperty(name="Wind", default=False,
                       description="Give the tree, and each tree of the forest, an armature "
                                   "with a looping wind action (Sylva's wind rig and clip, "
                                   "docs/wind.md)")
    wind_strength: FloatProperty(name="Strength", default=0.5, min=0.0, max=2.0)
    wind_gustiness: FloatProperty(name="Gustiness", default=0.3, min=0.0, max=1.0)
    wind_direction: FloatVectorProperty(name="Direction", size=3, default=(1.0, 0.0, 0.0),
                                        subtype="DIRECTION",
                                        description="Where the wind blows to (Blender axes; "
                                                    "only the horizontal part counts)")
    wind_bones: IntProperty(name="Bones", default=64, min=2, max=1024,
                            description="At most this many bones in the tree's armature")
    project_file: StringProperty(name="Project", subtype="FILE_PATH",
                                 description="A Sylva project (.sylva) saved by the editor: "
                                             "its trees with their branch edits")
    wind_clip: FloatProperty(name="Clip length", default=4.0, min=0.5, max=600.0, unit="TIME",
                             description="Seconds after which the wind action loops")


class SYLVA_OT_add_species(bpy.types.Operator):
    bl_idname = "sylva.add_species"
    bl_label = "Add species"
    bl_description = "Add a species and its tree count to the forest"

    def execute(self, context):
        s = context.scene.sylva
        s.species.add()
        s.active = len(s.species) - 1
        return {"FINISHED"}


class SYLVA_OT_remove_species(bpy.types.Operator):
    bl_idname = "sylva.remove_species"
    bl_label = "Remove species"

    index: IntProperty()

    def execute(self, context):
        context.scene.sylva.species.remove(self.index)
        return {"FINISHED"}


class SYLVA_OT_grow_tree(bpy.types.Operator):
    bl_idname = "sylva.grow_tree"
    bl_label = "Grow tree at cursor"
    bl_description = "Grow one tree of the chosen species at the 3D cursor"
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        s = context.scene.sylva
        try:
            sylva = import_sylva()
            path = bpy.path.abspath(s.tree_file) if s.tree_file else s.tree_preset
            tree = sylva.load_species(path).grow(seed=s.seed, wind=s.wind)
            if s.wind:
                # Through Sylva's wind GLB: the armature, the skin and the "wind" action are
                # the ones every other exporter writes (one model, docs/wind.md).
                build.wind_tree_objects(context, tree, s, context.scene.cursor.location)
                return {"FINISHED"}
        except (ImportError, ValueError, OSError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        obj = build.tree_object(context.scene.collection, tree.species, tree.mesh,
                                build.materials(sylva))
        obj.location = context.scene.cursor.location
        return {"FINISHED"}


def _build_reporting(operator, make):
    """Runs a forest build for \p operator: its result, or None with the error or the
    interruption reported (the grow-forest and import-project buttons)."""
    try:
        return make()
    except (ImportError, ValueError, OSError) as e:
        operator.report({"ERROR"}, str(e))
    except KeyboardInterrupt:
        operator.report({"WARNING"}, "interrupted")
    return None


class SYLVA_OT_grow_forest(bpy.types.Operator):
    bl_idname = "sylva.grow_forest"
    bl_label = "Grow forest"
    bl_description = ("Grow the forest over the ground object around the obstacle meshes "
                      "(replaces the last one: press again after moving an obstacle)")
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        forest = _build_reporting(
            self, lambda: build.grow_forest(import_sylva(), context, context.scene.sylva))
        if forest is None:
            return {"CANCELLED"}
        st = forest.stats
        self.report({"INFO"}, f"{st['trees']} trees ({st['instanced']} instanced, "
                              f"{st['variants']} variants), {st['triangles']} triangles, "
                              f"{st['colliding_trees']} met an obstacle, "
                              f"CO2 {st['metrics']['co2_kg']:.0f} kg")
        return {"FINISHED"}


class SYLVA_OT_import_project(bpy.types.Operator):
    bl_idname = "sylva.import_project"
    bl_label = "Import project"
    bl_description = ("Build the trees of a Sylva project file, with its hand edits of single "
                      "branches (replaces the last import: press again after the project "
                      "changed)")
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        s = context.scene.sylva
        forest = _build_reporting(
            self, lambda: build.import_project(import_sylva(), context, s.project_file, s))
        if forest is None:
            return {"CANCELLED"}
        st = forest.stats
        message = (f"{st['trees']} trees, {st['triangles']} triangles, "
                   f"{st['branch_edits']} branch edits applied")
        if st.get("orphaned_edits"):
            message += f", {st['orphaned_edits']} orphaned (their branch is gone)"
        self.report({"WARNING"} if st.get("orphaned_edits") else {"INFO"}, message)
        return {"FINISHED"}


class SYLVA_PT_panel(bpy.types.Panel):
    bl_label = "Sylva"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Sylva"

    def draw(self, context):
        s = context.scene.sylva
        layout = self.layout
        box = layout.box()
        box.label(text="Tree")
        box.prop(s, "tree_preset")
        box.prop(s, "tree_file")
        box.prop(s, "seed")
        box.prop(s, "wind")
        if s.wind:
            col = box.column(align=True)
            col.prop(s, "wind_strength")
            col.prop(s, "wind_gustiness")
            col.prop(s, "wind_direction")
            col.prop(s, "wind_bones")
            col.prop(s, "wind_clip")
        box.operator(SYLVA_OT_grow_tree.bl_idname, icon="OUTLINER_OB_FORCE_FIELD")
        box = layout.box()
        box.label(text="Forest")
        box.prop(s, "ground")
        box.prop(s, "obstacles")
        for i, item in enumerate(s.species):
            row = box.row(align=True)
            row.prop(item, "preset", text="")
            row.prop(item, "count", text="")
            row.operator(SYLVA_OT_remove_species.bl_idname, text="", icon="X").index = i
            if item.file or i == s.active:
                box.prop(item, "file")
        box.operator(SYLVA_OT_add_species.bl_idname, icon="ADD")
        box.prop(s, "seed")
        box.prop(s, "adapt")
        box.prop(s, "lod")
        box.prop(s, "instancing")
        box.prop(s, "auto_regrow")
        box.operator(SYLVA_OT_grow_forest.bl_idname, icon="OUTLINER_COLLECTION")
        box = layout.box()
        box.label(text="Project")
        box.prop(s, "project_file")
        box.operator(SYLVA_OT_import_project.bl_idname, icon="IMPORT")


_regrow_pending = False


def _watched(settings):
    names = {settings.ground.name} if settings.ground is not None else set()
    if settings.obstacles is not None:
        names |= {o.name for o in settings.obstacles.all_objects}
    return names


def _on_depsgraph_update(scene, depsgraph):
    """Schedules a regrow when the ground or an obstacle moved or changed shape."""
    global _regrow_pending
    settings = getattr(scene, "sylva", None)
    if settings is None or not settings.auto_regrow or _regrow_pending:
        return
    if bpy.data.collections.get(FOREST_COLLECTION) is None:
        return  # nothing grown yet
    watched = _watched(settings)
    for update in depsgraph.updates:
        obj = update.id.original if update.id else None
        if isinstance(obj, bpy.types.Object) and obj.name in watched and (
                update.is_updated_transform or update.is_updated_geometry):
            _regrow_pending = True
            bpy.app.timers.register(regrow_now, first_interval=0.3)
            return


def regrow_now():
    """The scheduled regrow (a timer; also callable directly)."""
    global _regrow_pending
    _regrow_pending = False
    try:
        build.grow_forest(import_sylva(), bpy.context, bpy.context.scene.sylva)
    except (ImportError, ValueError, OSError) as e:
        print("sylva: regrow failed:", e)
    return None


def regrow_pending():
    return _regrow_pending


CLASSES = (SylvaSpeciesCount, SylvaSettings, SYLVA_OT_add_species, SYLVA_OT_remove_species,
           SYLVA_OT_grow_tree, SYLVA_OT_grow_forest, SYLVA_OT_import_project, SYLVA_PT_panel)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.Scene.sylva = PointerProperty(type=SylvaSettings)
    bpy.app.handlers.depsgraph_update_post.append(_on_depsgraph_update)


def unregister():
    if _on_depsgraph_update in bpy.app.handlers.depsgraph_update_post:
        bpy.app.handlers.depsgraph_update_post.remove(_on_depsgraph_update)
    if bpy.app.timers.is_registered(regrow_now):
        bpy.app.timers.unregister(regrow_now)
    del bpy.types.Scene.sylva
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
