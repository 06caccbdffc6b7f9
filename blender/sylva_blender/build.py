"""Blender meshes ↔ Sylva: Sylva is Y-up, Blender Z-up; a Sylva point (x, y, z) is Blender's
(x, -z, y)."""
import os
import tempfile

import bpy
import numpy as np

FOREST_COLLECTION = "Sylva Forest"
PROJECT_COLLECTION = "Sylva Project"  # import_project's trees


def to_blender(p):
    """(N, 3) Sylva (Y-up) → Blender (Z-up)."""
    return np.stack([p[:, 0], -p[:, 2], p[:, 1]], axis=1)


def to_sylva(p):
    """(N, 3) Blender (Z-up) → Sylva (Y-up)."""
    return np.stack([p[:, 0], p[:, 2], -p[:, 1]], axis=1)


def world_triangles(obj, depsgraph):
    """An object's evaluated mesh as world-space (Sylva axes) vertices and triangles."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        mesh.calc_loop_triangles()
        n = len(mesh.vertices)
        co = np.empty(n * 3, dtype=np.float64)
        mesh.vertices.foreach_get("co", co)
        co = co.reshape(n, 3)
        m = np.array(obj.matrix_world, dtype=np.float64)
        world = co @ m[:3, :3].T + m[:3, 3]
        tris = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
        mesh.loop_triangles.foreach_get("vertices", tris)
        return to_sylva(world), tris.reshape(-1, 3)
    finally:
        evaluated.to_mesh_clear()


def _image(path):
    name = os.path.basename(path)
    img = bpy.data.images.get(name)
    if img is None and os.path.exists(path):
        img = bpy.data.images.load(path, check_existing=True)
    return img


# The colour attribute holding the leaf tints (linear multipliers of the leaf texture).
TINT_ATTRIBUTE = "sylva_tint"


def _material(name, texture, leaf):
    mat = bpy.data.materials.get(name)
    if mat is not None:
        return mat
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    bsdf = nodes.get("Principled BSDF")
    bsdf.inputs["Base Color"].default_value = (0.3, 0.5, 0.2, 1) if leaf else (0.35, 0.25, 0.2, 1)
    img = _image(texture) if texture else None
    if img is not None:
        tex = nodes.new("ShaderNodeTexImage")
        tex.image = img
        color = tex.outputs["Color"]
        if leaf:
            # Each leaf card's tint (sylva.Mesh.colors, the colour attribute TINT_ATTRIBUTE,
            # white where a species sets no variation) multiplies the texture, as glTF's
            # COLOR_0 does.
            tint = nodes.new("ShaderNodeVertexColor")
            tint.layer_name = TINT_ATTRIBUTE
            mix = nodes.new("ShaderNodeMixRGB")
            mix.blend_type = "MULTIPLY"
            mix.inputs["Fac"].default_value = 1.0
            mat.node_tree.links.new(color, mix.inputs["Color1"])
            mat.node_tree.links.new(tint.outputs["Color"], mix.inputs["Color2"])
            color = mix.outputs["Color"]
        mat.node_tree.links.new(color, bsdf.inputs["Base Color"])
        if leaf:
            mat.node_tree.links.new(tex.outputs["Alpha"], bsdf.inputs["Alpha"])
            mat.blend_method = "CLIP"
            mat.shadow_method = "CLIP"
    mat.use_backface_culling = False
    return mat


def materials(sylva):
    """Sylva's bark and leaf materials with the shipped textures, by Sylva material name."""
    textures = os.path.join(sylva.resources_dir(), "textures") if sylva.resources_dir() else ""

    def tex(*names):
        for n in names:
            p = os.path.join(textures, n)
            if os.path.exists(p):
                return p
        return ""

    return {"bark": _material("Sylva Bark", tex("bark.png"), False),
            "leaf": _material("Sylva Leaf", tex("leaf.png"), True)}


def mesh_data(name, mesh, mats):
    """A Blender mesh from a sylva.Mesh (numpy arrays), with UVs, normals and materials."""
    me = bpy.data.meshes.new(name)
    positions = to_blender(mesh.positions)
    tris = mesh.indices
    nv, nt = len(positions), len(tris)
    me.vertices.add(nv)
    me.vertices.foreach_set("co", positions.astype(np.float32).ravel())
    me.loops.add(nt * 3)
    me.loops.foreach_set("vertex_index", tris.astype(np.int32).ravel())
    me.polygons.add(nt)
    me.polygons.foreach_set("loop_start", np.arange(0, nt * 3, 3, dtype=np.int32))
    me.polygons.foreach_set("loop_total", np.full(nt, 3, dtype=np.int32))
    names = mesh.materials
    mat_index = np.zeros(nt, dtype=np.int32)
    for k, (mat, first, count) in enumerate(mesh.submeshes):
        mat_index[first:first + count] = names.index(mat)
    for n in names:
        me.materials.append(mats.get(n))
    me.polygons.foreach_set("material_index", mat_index)
    if len(mesh.uvs):
        uv = me.uv_layers.new(name="UVMap")
        uv.data.foreach_set("uv", mesh.uvs[tris.ravel()].astype(np.float32).ravel())
    # The leaf tints, always present so that the leaf material's multiply finds them: white
    # where the species sets no variation. Byte colours (4 bytes a vertex); .color is linear.
    tint = me.color_attributes.new(TINT_ATTRIBUTE, "BYTE_COLOR", "POINT")
    colors = np.ones((nv, 4), dtype=np.float32)
    if len(mesh.colors) == nv:
        colors = mesh.colors.astype(np.float32) / 255.0
    tint.data.foreach_set("color", colors.ravel())
    me.update()
    if len(mesh.normals):
        me.use_auto_smooth = True
        me.polygons.foreach_set("use_smooth", np.ones(nt, dtype=bool))
        me.normals_split_custom_set_from_vertices(to_blender(mesh.normals).tolist())
    return me


def tree_object(collection, name, mesh, mats):
    obj = bpy.data.objects.new(name, mesh_data(name, mesh, mats))
    collection.objects.link(obj)
    return obj


def _import_wind_glb(owner, settings):
    """\p owner (a sylva.Tree or sylva.Forest) written as Sylva's wind GLB with the wind of
    \p settings and imported with Blender's glTF importer; returns the objects it made."""
    import numpy
    numpy.bool = bool  # Blender 3.4's glTF importer still uses the removed alias
    d = settings.wind_direction
    with tempfile.TemporaryDirectory(prefix="sylva-wind-") as folder:
        glb = os.path.join(folder, "wind.glb")
        owner.export(glb, wind=True, direction=(d[0], d[2], -d[1]),
                     strength=settings.wind_strength, gustiness=settings.wind_gustiness,
                     bones=settings.wind_bones, clip_length=settings.wind_clip)
        before = set(bpy.data.objects)
        bpy.ops.import_scene.gltf(filepath=glb)
    return [o for o in bpy.data.objects if o not in before]


def _cover_clip(scene, frames):
    """Widens the scene's frame range to \p frames when shorter, so playback shows a loop."""
    scene.frame_end = max(scene.frame_end, scene.frame_start + int(frames))


def _clip_frames(obj):
    """The length in frames of \p obj's action, 0 without one."""
    action = obj.animation_data.action if obj.animation_data else None
    return action.frame_range[1] - action.frame_range[0] if action is not None else 0.0


def _tag_forest_tree(obj, tree, variants):
    """The forest tree's identity as custom properties of its object (exports carry it too)."""
    obj["sylva_species"] = tree.species
    obj["sylva_seed"] = str(tree.seed)  # 64-bit: too large for an ID property int
    obj["sylva_id"] = str(tree.id)  # the tree's stable id
    obj["sylva_variant"] = variants[tree.variant].name if tree.instanced else ""


def wind_tree_objects(context, tree, settings, location):
    """A grown sylva tree with wind: written as Sylva's wind GLB (rig of at most
    settings.wind_bones bones, skin, the looping "wind" clip) and imported with Blender's glTF
    importer, so that the tree is an armature (its root at \p location) with the wind action
    and the skinned mesh as its child. Returns the armature. The scene's frame range is widened
    to the clip when shorter, so that playback shows a whole loop."""
    new = _import_wind_glb(tree, settings)
    armatures = [o for o in new if o.type == "ARMATURE"]
    if len(armatures) != 1:
        raise ValueError(f"the wind GLB gave {len(armatures)} armatures, expected one")
    armature = armatures[0]
    armature.name = tree.species
    for obj in new:
        if obj.parent is None:
            obj.location = obj.location + location
    _cover_clip(context.scene, _clip_frames(armature))
    armature["sylva_species"] = tree.species
    if tree.seed is not None:
        armature["sylva_seed"] = str(tree.seed)
    return armature


def forest_collection(scene, name=None):
    """The forest's collection (or the one called \p name), emptied (its meshes removed too),
    or a new one."""
    name = name or FOREST_COLLECTION
    col = bpy.data.collections.get(name)
    if col is None:
        col = bpy.data.collections.new(name)
        scene.collection.children.link(col)
    actions = set()
    for obj in list(col.objects):
        data = obj.data
        if obj.animation_data and obj.animation_data.action:
            actions.add(obj.animation_data.action)
        bpy.data.objects.remove(obj, do_unlink=True)
        if data is not None and data.users == 0:
            if isinstance(data, bpy.types.Mesh):
                bpy.data.meshes.remove(data)
            elif isinstance(data, bpy.types.Armature):
                bpy.data.armatures.remove(data)
    for action in actions:  # a wind forest's actions, one per armature
        if action.users == 0:
            bpy.data.actions.remove(action)
    return col


def grow_forest(sylva, context, settings):
    """Builds the forest of \\p settings (SylvaSettings) and puts it in the "Sylva Forest"
    collection, one object per tree (instanced trees share their variant's mesh; with Wind, an
    armature per tree with its wind action, wind_forest_objects); returns the sylva.Forest."""
    if settings.ground is None:
        raise ValueError("choose a ground object")
    depsgraph = context.evaluated_depsgraph_get()
    project = sylva.Project(seed=settings.seed)
    counts = {}
    for i, item in enumerate(settings.species):
        path = item.species_path()
        if not path or item.count == 0:
            continue
        name = f"{os.path.splitext(os.path.basename(path))[0]}-{i + 1}"
        project.add_species(name, path)
        counts[name] = item.count
    if not counts:
        raise ValueError("add a species with a tree count")
    vertices, triangles = world_triangles(settings.ground, depsgraph)
    project.set_ground(vertices, triangles, counts=counts, name=settings.ground.name)
    if settings.obstacles is not None:
        for obj in settings.obstacles.all_objects:
            if obj.type == "MESH" and obj != settings.ground:
                v, t = world_triangles(obj, depsgraph)
                if len(t):
                    project.add_obstacle(vertices=v, triangles=t, name=obj.name)
    camera = None
    if settings.lod and context.scene.camera is not None:
        c = context.scene.camera.matrix_world.translation
        camera = (c.x, c.z, -c.y)
    wm = context.window_manager
    wm.progress_begin(0, 100)
    try:
        forest = project.build_forest(progress=lambda f, stage: wm.progress_update(int(f * 100)),
                                      camera=camera, lod=settings.lod, adapt=settings.adapt,
                                      instancing=settings.instancing, wind=settings.wind)
    finally:
        wm.progress_end()

    col = forest_collection(context.scene)
    if settings.wind:
        wind_forest_objects(context, forest, settings, col)
        return forest
    forest_objects(sylva, forest, col, settings.lod)
    return forest


def import_project(sylva, context, path, settings):
    """Builds the Sylva project file \p path (a .sylva, as the editor saved it: its species,
    trees, domains, obstacles, camera and each hand-placed tree's branch edits) as `sylva-cli
    forest` builds it, and puts its trees in the "Sylva Project" collection, replacing those of
    the last import: importing again after the project changed is its regrow. The branch
    edits are the project's own, applied by the engine after growth, so every import keeps
    them. Adapt, Level of detail (from the project's camera) and Share variants are \p settings'.
    Returns the sylva.Forest."""
    path = bpy.path.abspath(path)
    if not path:
        raise ValueError("choose a Sylva project file (.sylva)")
    project = sylva.load_project(path)
    wm = context.window_manager
    wm.progress_begin(0, 100)
    try:
        forest = project.build_forest(progress=lambda f, stage: wm.progress_update(int(f * 100)),
                                      lod=settings.lod, adapt=settings.adapt,
                                      instancing=settings.instancing)
    finally:
        wm.progress_end()
    col = forest_collection(context.scene, PROJECT_COLLECTION)
    forest_objects(sylva, forest, col, settings.lod)
    for obj in col.objects:
        obj["sylva_project"] = path
    return forest


def forest_objects(sylva, forest, col, lod):
    """One object per tree of \p forest in \p col (Y-up metres to Blender's Z-up), each tagged
    with its ids; without \p lod, instanced trees link their variant's one mesh."""
    mats = materials(sylva)
    variants = forest.variants
    shared = {}  # variant index -> its one Blender mesh, linked by every tree that shows it
    for tree in forest.trees:
        # Without the camera's LOD an instanced tree shows its variant's very mesh: a linked
        # duplicate (one mesh datablock per variant), so 10,000 trees stay light. With it, each
        # tree has its own level of detail and its own mesh.
        if tree.instanced and not lod:
            data = shared.get(tree.variant)
            if data is None:
                v = variants[tree.variant]
                data = shared[tree.variant] = mesh_data(v.name, v.mesh, mats)
            obj = bpy.data.objects.new(tree.name, data)
            col.objects.link(obj)
        else:
            obj = tree_object(col, tree.name, tree.mesh, mats)
        x, y, z = tree.position
        obj.location = (x, -z, y)
        obj.rotation_euler = (0.0, 0.0, tree.rotation)  # about Sylva's +Y = Blender's +Z
        obj.scale = (tree.scale,) * 3
        _tag_forest_tree(obj, tree, variants)


def wind_forest_objects(context, forest, settings, col):
    """The forest with wind (as "Grow tree at cursor" with Wind): written as Sylva's wind GLB
    (sylva.Forest.export(wind=True): per tree a rig and the looping "wind" clip, instances of
    a variant sharing its mesh) and imported with Blender's glTF importer into \p col: each tree
    an armature with its "wind" action and its skinned mesh as the child. Blender's importer
    makes one mesh per skinned node; the trees of a variant are given back one shared mesh
    datablock (their vertex groups name their own bones in the same joint order)."""
    new = _import_wind_glb(forest, settings)
    for obj in new:
        for c in list(obj.users_collection):
            c.objects.unlink(obj)
        col.objects.link(obj)
    by_name = {o.name: o for o in new}
    variants = forest.variants
    shared = {}  # variant index -> the mesh datablock its trees link
    longest = 0.0
    for tree in forest.trees:
        armature = by_name.get(tree.name)
        if armature is None or armature.type != "ARMATURE":
            continue  # a tree pruned away has no rig
        _tag_forest_tree(armature, tree, variants)
        longest = max(longest, _clip_frames(armature))
        skinned = by_name.get(tree.name + "_mesh")
        if skinned is None or not tree.instanced:
            continue
        data = shared.get(tree.variant)
        if data is None:
            shared[tree.variant] = skinned.data
            skinned.data.name = variants[tree.variant].name
        elif skinned.data != data:
            old = skinned.data
            skinned.data = data
            if old.users == 0:
                bpy.data.meshes.remove(old)
    _cover_clip(context.scene, longest)
