# Headless check of the Blender add-on (tools/blender/arbor_blender), run by CTest as
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/add_tree.py -- <arbor module folder>
# Registers the add-on from the source tree, runs Add > Arbor Tree, and exits non-zero unless the tree object
# has the module's quads, the leaves object exists, and the bark material has its image texture.
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, run_checks  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
args = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
if args:
    os.environ["ARBOR_PYTHONPATH"] = args[0]  # where the add-on looks for the module (Blender ignores PYTHONPATH)
sys.path.insert(0, os.path.join(SOURCE, "tools", "blender"))

PRESET, SEED, LEVELS = "black-tupelo", 3, 2

def image_nodes(material):
    return [n for n in material.node_tree.nodes if n.type == "TEX_IMAGE" and n.image is not None]


def run():
    import arbor_blender
    from arbor_blender import module

    arbor_blender.register()
    arbor = module.load()
    print(f"arbor {arbor.__version__} from {arbor.__file__}; Blender {bpy.app.version_string}")
    check(PRESET in [item[0] for item in arbor_blender.operators.preset_items(None, bpy.context)], "the operator offers the presets")

    result = bpy.ops.mesh.arbor_tree_add(preset=PRESET, seed=SEED, levels=LEVELS)
    check(result == {"FINISHED"}, f"Add Arbor Tree finished ({result})")
    tree = arbor.grow(PRESET, seed=SEED, levels=LEVELS)
    expected = tree.mesh()

    obj = bpy.data.objects.get(tree.name)
    check(obj is not None and obj.type == "MESH", f"tree object '{tree.name}' exists")
    if obj is None:
        return
    check(bpy.context.view_layer.objects.active == obj, "the tree is the active object")
    polygons = obj.data.polygons
    check(len(polygons) == expected.quad_count, f"{len(polygons)} faces == the module's {expected.quad_count} quads")
    check(all(p.loop_total == 4 for p in polygons), "every face is a quad")
    check(len(obj.data.vertices) == expected.vertex_count, f"{len(obj.data.vertices)} vertices == {expected.vertex_count}")
    check(tuple(obj.data.polygons[0].vertices) == tuple(int(i) for i in expected.quads[0]), "faces keep the module's vertex order")
    check("UVMap" in obj.data.uv_layers, "UV map from uvw.xy")
    check(all(name in obj.data.attributes for name in ("flip", "radius", "level")), "flip, radius and level attributes")
    check(any(m.type == "SUBSURF" for m in obj.modifiers), "Subdivision Surface modifier")
    # z up as in Arbor: the tree stands on the origin and rises along +z
    top = max(v.co.z for v in obj.data.vertices)
    check(top > 1.0 and abs(min(v.co.z for v in obj.data.vertices)) < 0.5, f"upright (top at z = {top:.2f} m)")

    bark = obj.active_material
    check(bark is not None and bark.use_nodes, "the tree has a node material")
    if bark is not None:
        images = image_nodes(bark)
        check(any(os.path.basename(n.image.filepath) == "bark_color.png" for n in images), "bark material has the bark_color.png image texture")
        check(all(n.image.size[0] > 0 for n in images), "its images load")
        bsdf = bark.node_tree.nodes.get("Principled BSDF")
        check(bsdf is not None and bsdf.inputs["Base Color"].is_linked, "the texture feeds the Principled BSDF's Base Color")

    leaves = [c for c in obj.children if c.type == "MESH"]
    check(len(leaves) == 1, "a leaves object, parented to the tree")
    if leaves:
        count = len(tree.leaves["position"])
        check(len(leaves[0].data.polygons) == count and count > 0, f"{len(leaves[0].data.polygons)} leaf cards == {count} leaves")
        material = leaves[0].active_material
        check(material is not None and material.blend_method == "CLIP", "leaf material is alpha-clipped")
        if material is not None:
            check(any(os.path.basename(n.image.filepath) == "leaf_atlas.png" for n in image_nodes(material)), "leaf material has leaf_atlas.png")
            check(material.node_tree.nodes["Principled BSDF"].inputs["Alpha"].is_linked, "the atlas's alpha masks the leaves")

    # A bad preset is reported, not a crash.
    try:
        bpy.ops.mesh.arbor_tree_add(preset="no-such-preset")
        check(False, "an unknown preset is refused")
    except TypeError as error:  # Blender refuses an enum value it does not offer
        check("no-such-preset" in str(error), "an unknown preset is refused")

    if os.environ.get("ARBOR_BLEND_OUT"):
        bpy.ops.wm.save_as_mainfile(filepath=os.environ["ARBOR_BLEND_OUT"])


run_checks(run, "arbor blender add-on")
