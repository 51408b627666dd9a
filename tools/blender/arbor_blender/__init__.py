# Arbor's trees in Blender: Add > Arbor Tree grows a tree with the `arbor` Python module and adds it as a quad
# mesh (bark material, Subdivision Surface) with its leaves as a second object of alpha-masked cards.
# The module is a build product (build/python/arbor.cpython-*.so): on Blender's Python path, or in the folder
# the add-on's preferences name, or in $ARBOR_PYTHONPATH. See docs/python.md.
bl_info = {
    "name": "Arbor Trees",
    "author": "Arbor",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Add > Arbor Tree",
    "description": "Grows Weber-Penn, L-system and space-colonization trees with Arbor: one closed quad mesh with bark and leaves",
    "category": "Add Mesh",
}

if "bpy" in locals():  # F8 / script reload: pick up edited submodules
    import importlib

    importlib.reload(module)  # noqa: F821
    importlib.reload(build)  # noqa: F821
    importlib.reload(operators)  # noqa: F821

import bpy

from . import build, module, operators


class ArborPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_path: bpy.props.StringProperty(
        name="arbor module folder",
        description="Folder holding the arbor Python module (Arbor's build/python); empty: Blender's Python path or $ARBOR_PYTHONPATH",
        subtype="DIR_PATH",
        default="",
    )

    def draw(self, context):
        self.layout.prop(self, "module_path")
        self.layout.label(text=module.status())


def menu_entry(self, context):
    self.layout.operator(operators.ARBOR_OT_tree_add.bl_idname, text="Arbor Tree", icon="OUTLINER_OB_MESH")


classes = (ArborPreferences, operators.ARBOR_OT_tree_add)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_add.append(menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_add.remove(menu_entry)
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
