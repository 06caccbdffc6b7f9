"""How far an imported wind clip moves a tree in Blender, shared by the wind import tests
(test_wind_glb.py, test_wind_fbx.py): the tip of the tallest branch against a point on the lower
trunk, sampled every 6 frames, and how far the last frame is from the first (a looping clip)."""
import bpy
from mathutils import Vector


def world_positions(meshes):
    """The evaluated (skinned) vertices of `meshes` in world space, at the scene's frame."""
    out = []
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for mesh in meshes:
        evaluated = mesh.evaluated_get(depsgraph)
        m = evaluated.to_mesh()
        out += [mesh.matrix_world @ v.co for v in m.vertices]
        evaluated.to_mesh_clear()
    return out


def measure_motion(meshes, first, last):
    """Returns (height, tip_moved, low_moved, loop) over frames first..last."""
    scene = bpy.context.scene
    scene.frame_set(first)
    rest = world_positions(meshes)
    zs = [v.z for v in rest]
    height = max(zs) - min(zs)
    tip = max(range(len(rest)), key=lambda i: rest[i].z)
    # A point on the lower trunk: the vertex nearest the axis at a tenth of the height.
    low = min(range(len(rest)),
              key=lambda i: abs(rest[i].z - min(zs) - 0.1 * height) + Vector(rest[i].xy).length)
    tip_moved = low_moved = 0.0
    for frame in range(first, last + 1, 6):
        scene.frame_set(frame)
        p = world_positions(meshes)
        tip_moved = max(tip_moved, (p[tip] - rest[tip]).length)
        low_moved = max(low_moved, (p[low] - rest[low]).length)
    scene.frame_set(last)
    loop = max((a - b).length for a, b in zip(world_positions(meshes), rest))
    return height, tip_moved, low_moved, loop


def assert_sways(tip_moved, low_moved, loop):
    """The crown moves, the trunk much less, and the clip loops."""
    assert tip_moved > 0.05, tip_moved
    assert tip_moved >= 5 * low_moved, (tip_moved, low_moved)
    assert loop < 1e-3, loop
