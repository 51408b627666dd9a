# Add > Arbor Tree: grows a preset with the arbor module and adds it at the 3D cursor.
import bpy

from . import build, module

_preset_items = []  # Blender needs the enum's strings kept alive by Python


def preset_items(self, context):
    global _preset_items
    try:
        names = module.load().presets()
        _preset_items = [(name, name, f"Arbor preset '{name}'") for name in names]
    except (ImportError, ValueError) as error:
        _preset_items = [("NONE", "(arbor module not found)", str(error))]
    return _preset_items


class ARBOR_OT_tree_add(bpy.types.Operator):
    """Grow an Arbor tree and add it as a quad mesh with bark, subdivision and leaves"""

    bl_idname = "mesh.arbor_tree_add"
    bl_label = "Add Arbor Tree"
    bl_options = {"REGISTER", "UNDO"}

    preset: bpy.props.EnumProperty(name="Preset", description="Arbor preset (species, space-colonization or L-system)", items=preset_items)
    seed: bpy.props.IntProperty(name="Seed", description="Random seed: the same seed grows the same tree", default=1, min=0)
    levels: bpy.props.IntProperty(name="Levels", description="Stem levels to grow (0: the preset's own)", default=0, min=0, max=8)
    leaves: bpy.props.BoolProperty(name="Leaves", description="Add the leaves as alpha-masked cards", default=True)
    subdivision: bpy.props.IntProperty(name="Subdivision", description="Subdivision Surface levels in the viewport", default=1, min=0, max=4)
    render_subdivision: bpy.props.IntProperty(name="Render Subdivision", description="Subdivision Surface levels when rendering", default=2, min=0, max=4)

    def execute(self, context):
        try:
            arbor = module.load()
        except ImportError as error:
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        if self.preset == "NONE":
            self.report({"ERROR"}, "no Arbor preset to grow: the arbor module was not found")
            return {"CANCELLED"}
        try:
            tree = arbor.grow(self.preset, seed=self.seed, levels=self.levels)
            tree_object = build.add_tree(context, arbor, tree, self.subdivision, self.render_subdivision, self.leaves)
        except (ValueError, OSError) as error:  # arbor.InputError, LimitError, a missing texture
            self.report({"ERROR"}, str(error))
            return {"CANCELLED"}
        for selected in context.selected_objects:
            selected.select_set(False)
        tree_object.select_set(True)
        context.view_layer.objects.active = tree_object
        self.report({"INFO"}, f"{tree.name}: {len(tree_object.data.polygons)} quads, {len(tree.leaves['position'])} leaves")
        return {"FINISHED"}
