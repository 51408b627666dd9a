# Headless check that Blender imports Arbor's exports as a user would, run by CTest as
#   blender -b --factory-startup --python-exit-code 1 --python tests/blender/import_tree.py -- <arbor binary> <folder>
# Writes the palm as GLB and OBJ with `arbor generate`, imports each into an empty scene with Blender's own
# importers, and exits non-zero unless the tree stands upright (Blender is z up), has its leaves and its
# textures, and the bark keeps the mesh's face count; then a GLB with wind, whose animation Blender plays.
import os
import subprocess
import sys

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, run_checks  # noqa: E402

numpy.bool = bool  # Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which its numpy removed

arbor, folder = sys.argv[sys.argv.index("--") + 1 :][:2]


def generate(path, *options):
    result = subprocess.run([arbor, "generate", "palm", "--quiet", *options, "--out", path], capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"arbor generate failed: {result.stdout}{result.stderr}")


def textured(material):
    return any(n.type == "TEX_IMAGE" and n.image is not None and n.image.size[0] > 0 for n in material.node_tree.nodes)


def world_bounds(objects):
    corners = [o.matrix_world @ v.co for o in objects for v in o.data.vertices]
    return [min(c[k] for c in corners) for k in range(3)], [max(c[k] for c in corners) for k in range(3)]


def check_import(kind, objects, bark_faces):
    meshes = [o for o in objects if o.type == "MESH"]
    materials = {m.name.split(".")[0]: m for o in meshes for m in o.data.materials if m is not None}
    check("bark" in materials and "leaves" in materials, f"{kind}: bark and leaves materials ({sorted(materials)})")
    lo, hi = world_bounds(meshes)
    height, width = hi[2] - lo[2], max(hi[0] - lo[0], hi[1] - lo[1])
    check(abs(lo[2]) < 0.05 and height > 10.0 and height > width, f"{kind}: upright, base at 0, {height:.1f} m tall, {width:.1f} m wide")
    check(textured(materials["bark"]) and textured(materials["leaves"]), f"{kind}: bark and leaf textures loaded")
    leaves = materials["leaves"]
    check(leaves.blend_method in ("CLIP", "HASHED", "BLEND"), f"{kind}: leaves are alpha-masked ({leaves.blend_method})")
    faces = sum(sum(1 for p in o.data.polygons if o.data.materials[p.material_index].name.split(".")[0] == "bark") for o in meshes)
    check(faces == bark_faces, f"{kind}: {faces} bark faces, the mesh has {bark_faces} quads ({'x2 triangles' if kind == 'GLB' else 'quads'})")


def bark_quads(obj_path):
    quads = 0
    with open(obj_path) as f:
        for line in f:
            if line.startswith("o "):
                break
            quads += line.startswith("f ")
    return quads


def run():
    glb, obj = os.path.join(folder, "palm.glb"), os.path.join(folder, "palm.obj")
    generate(glb)
    generate(obj)
    quads = bark_quads(obj)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=glb)
    check_import("GLB", list(bpy.context.scene.objects), 2 * quads)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.obj_import(filepath=obj)  # Blender's default for OBJ: y up in the file
    check_import("OBJ", list(bpy.context.scene.objects), quads)

    # Wind: morph targets become shape keys, the loop an action Blender plays.
    windy = os.path.join(folder, "palm-wind.glb")
    generate(windy, "--wind", "1", "--wind-frames", "8")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=windy)
    scene = bpy.context.scene
    tree = [o for o in scene.objects if o.type == "MESH"][0]
    keys = tree.data.shape_keys
    check(keys is not None and len(keys.key_blocks) == 9, "wind: 8 shape keys and the basis")
    action = keys.animation_data.action if keys is not None and keys.animation_data else None
    check(action is not None and action.frame_range[1] > action.frame_range[0], "wind: an action plays the shape keys")

    def evaluated(frame):
        scene.frame_set(frame)
        posed = tree.evaluated_get(bpy.context.evaluated_depsgraph_get())
        positions = [v.co.copy() for v in posed.to_mesh().vertices]
        posed.to_mesh_clear()
        return positions

    first, later = evaluated(1), evaluated(30)
    moved = max((a - b).length for a, b in zip(first, later))
    check(0.01 < moved < 2.0, f"wind: the tree moves between frames 1 and 30 (at most {moved:.3f} m)")


run_checks(run, "Blender imports")
