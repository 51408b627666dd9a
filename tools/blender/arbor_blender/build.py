# Blender data from an arbor.Tree: the bark mesh, the leaf cards and their materials. Arbor is z up in metres,
# as Blender is: positions go in unchanged.
import os

import bpy
import numpy as np

# The share of its atlas cell's width each leaf kind's blade fills (broad, narrow, frond, needle), as the
# renderer's leaf.geom has it: the card is widened so that the blade itself has the leaf's width.
BLADE_SHARE = np.array([0.82, 0.30, 0.95, 0.70])


def _smooth(mesh):
    if hasattr(mesh, "shade_smooth"):  # Blender 4.1 and later
        mesh.shade_smooth()
    else:
        mesh.polygons.foreach_set("use_smooth", np.ones(len(mesh.polygons), dtype=bool))


def _point_attribute(mesh, name, values):
    attribute = mesh.attributes.new(name=name, type="FLOAT", domain="POINT")
    attribute.data.foreach_set("value", np.ascontiguousarray(values, dtype=np.float32).ravel())


def _corner_uvs(mesh, uv):
    """Per-vertex (V, 2) texture coordinates onto the mesh's face corners as its UV map."""
    corners = np.empty(len(mesh.loops), dtype=np.int32)
    mesh.loops.foreach_get("vertex_index", corners)
    layer = mesh.uv_layers.new(name="UVMap")
    layer.data.foreach_set("uv", np.ascontiguousarray(uv[corners], dtype=np.float32).ravel())


def bark_mesh(name, mesh):
    """The tree's quad mesh (arbor.Mesh) as a Blender mesh: quads as they are, UVs from uvw.xy, and the point
    attributes flip (uvw.z, the flip coordinate the bark material uses), radius and level."""
    data = bpy.data.meshes.new(name)
    data.from_pydata(mesh.positions.tolist(), [], mesh.quads.tolist())
    _corner_uvs(data, mesh.uvw[:, :2])
    _point_attribute(data, "flip", mesh.uvw[:, 2])
    _point_attribute(data, "radius", mesh.radius)
    _point_attribute(data, "level", mesh.level)
    _smooth(data)
    data.validate()
    data.update()
    return data


def leaf_cards(name, leaves):
    """One quad per leaf (Tree.leaves), counter-clockwise around the leaf's normal, base to tip, textured with
    its kind's cell of the 2 x 2 leaf atlas (blade base at the bottom centre of the cell)."""
    count = len(leaves["position"])
    base, along, normal = leaves["position"], leaves["direction"], leaves["normal"]
    kind = np.minimum(leaves["kind"].astype(np.int64), 3)
    half = (0.5 * leaves["width"] / BLADE_SHARE[kind])[:, None]
    across = np.cross(along, normal)  # with `along`, spans the blade counter-clockwise seen from the normal side
    tip = base + along * leaves["length"][:, None]
    corners = np.stack([base - across * half, base + across * half, tip + across * half, tip - across * half], axis=1)
    # Atlas cell k: u from 0.5 (k % 2), v (Blender's, up the image) from 0.5 - 0.5 (k // 2). The corners take
    # the renderer's cell coordinates: the side towards cross(normal, direction) at the cell's right.
    cell = np.stack([0.5 * (kind % 2), 0.5 - 0.5 * (kind // 2)], axis=1)
    offsets = np.array([[0.5, 0.0], [0.0, 0.0], [0.0, 0.5], [0.5, 0.5]])
    uv = (cell[:, None, :] + offsets[None, :, :]).reshape(-1, 2)

    data = bpy.data.meshes.new(name)
    quads = np.arange(4 * count, dtype=np.int64).reshape(count, 4)
    data.from_pydata(corners.reshape(-1, 3).tolist(), [], quads.tolist())
    _corner_uvs(data, uv)
    data.validate()
    data.update()
    return data


def _image(path, non_color=False):
    image = bpy.data.images.load(path, check_existing=True)
    if non_color:
        image.colorspace_settings.name = "Non-Color"
    return image


def _node(nodes, kind, location, **settings):
    node = nodes.new(kind)
    node.location = location
    for key, value in settings.items():
        setattr(node, key, value)
    return node


def _math(nodes, links, operation, a, b, location):
    node = _node(nodes, "ShaderNodeMath", location, operation=operation)
    for socket, value in zip(node.inputs, (a, b)):
        if isinstance(value, (int, float)):
            socket.default_value = value
        else:
            links.new(value, socket)
    return node.outputs[0]


def bark_material(textures):
    """Principled BSDF with Arbor's bark colour (and height as bump), mapped as the renderer maps it: u' = u / 2
    where the flip attribute is >= 0, else 1 - u / 2, so the mirrored u has no seam."""
    material = bpy.data.materials.get("Arbor Bark")
    if material:
        return material
    material = bpy.data.materials.new("Arbor Bark")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    bsdf = nodes.get("Principled BSDF") or _node(nodes, "ShaderNodeBsdfPrincipled", (300, 300))
    bsdf.inputs["Roughness"].default_value = 0.85

    uv = _node(nodes, "ShaderNodeUVMap", (-1200, 300), uv_map="UVMap")
    flip = _node(nodes, "ShaderNodeAttribute", (-1200, 100), attribute_name="flip")
    split = _node(nodes, "ShaderNodeSeparateXYZ", (-1000, 300))
    links.new(uv.outputs["UV"], split.inputs[0])
    u = split.outputs["X"]
    back = _math(nodes, links, "LESS_THAN", flip.outputs["Fac"], 0.0, (-1000, 100))
    half = _math(nodes, links, "MULTIPLY", u, 0.5, (-800, 400))
    rest = _math(nodes, links, "SUBTRACT", 1.0, u, (-800, 200))
    shift = _math(nodes, links, "MULTIPLY", back, rest, (-650, 200))
    mapped_u = _math(nodes, links, "ADD", half, shift, (-500, 300))
    mapped = _node(nodes, "ShaderNodeCombineXYZ", (-350, 300))
    links.new(mapped_u, mapped.inputs["X"])
    links.new(split.outputs["Y"], mapped.inputs["Y"])

    color = _node(nodes, "ShaderNodeTexImage", (-150, 400), image=_image(os.path.join(textures, "bark_color.png")))
    links.new(mapped.outputs[0], color.inputs["Vector"])
    links.new(color.outputs["Color"], bsdf.inputs["Base Color"])
    height_path = os.path.join(textures, "bark_height.png")
    if os.path.exists(height_path):
        height = _node(nodes, "ShaderNodeTexImage", (-150, 100), image=_image(height_path, non_color=True))
        links.new(mapped.outputs[0], height.inputs["Vector"])
        bump = _node(nodes, "ShaderNodeBump", (100, 100))
        bump.inputs["Strength"].default_value = 0.6
        bump.inputs["Distance"].default_value = 0.01
        links.new(height.outputs["Color"], bump.inputs["Height"])
        links.new(bump.outputs["Normal"], bsdf.inputs["Normal"])
    return material


def leaf_material(textures):
    """Principled BSDF with the leaf atlas's colour, its alpha as a cut-out mask, both sides drawn."""
    material = bpy.data.materials.get("Arbor Leaves")
    if material:
        return material
    material = bpy.data.materials.new("Arbor Leaves")
    material.use_nodes = True
    material.blend_method = "CLIP"
    material.shadow_method = "CLIP"
    material.alpha_threshold = 0.5
    material.use_backface_culling = False
    nodes, links = material.node_tree.nodes, material.node_tree.links
    bsdf = nodes.get("Principled BSDF") or _node(nodes, "ShaderNodeBsdfPrincipled", (300, 300))
    bsdf.inputs["Roughness"].default_value = 0.6
    atlas = _node(nodes, "ShaderNodeTexImage", (-300, 300), image=_image(os.path.join(textures, "leaf_atlas.png")))
    links.new(atlas.outputs["Color"], bsdf.inputs["Base Color"])
    links.new(atlas.outputs["Alpha"], bsdf.inputs["Alpha"])
    return material


def add_tree(context, arbor, tree, subdivision=1, render_subdivision=2, leaves=True):
    """Adds the tree (and its leaves, parented to it) at the 3D cursor; returns the tree object."""
    textures = os.path.join(arbor.asset_dir(), "textures")
    mesh = tree.mesh()
    collection = context.collection
    tree_object = bpy.data.objects.new(tree.name, bark_mesh(tree.name, mesh))
    tree_object.data.materials.append(bark_material(textures))
    tree_object.location = context.scene.cursor.location
    tree_object["arbor_seed"] = str(tree.seed)  # an ID property int is 32-bit; seeds go to 2**64 - 1
    tree_object["arbor_levels"] = tree.levels
    modifier = tree_object.modifiers.new("Subdivision", "SUBSURF")
    modifier.levels = subdivision
    modifier.render_levels = render_subdivision
    collection.objects.link(tree_object)

    if leaves and len(tree.leaves["position"]) > 0:
        leaf_object = bpy.data.objects.new(tree.name + " leaves", leaf_cards(tree.name + " leaves", tree.leaves))
        leaf_object.data.materials.append(leaf_material(textures))
        leaf_object.parent = tree_object
        collection.objects.link(leaf_object)
    return tree_object
