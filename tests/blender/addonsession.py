"""The start the add-on tests share: the two folders after "--" on Blender's command line, the
add-on imported from the first and registered in an empty factory scene."""
import sys

import bpy


def start_addon():
    """Returns (the sylva_blender module, the second folder); the scene is empty."""
    addon_dir, second = sys.argv[sys.argv.index("--") + 1:][:2]
    sys.path.insert(0, addon_dir)
    import sylva_blender
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sylva_blender.register()
    return sylva_blender, second
