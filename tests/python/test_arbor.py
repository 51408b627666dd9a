# The Python module as users call it: presets, growth, skeleton, leaves, the closed quad mesh, exports, errors.
import json
import pathlib
import struct

import numpy as np
import pytest

import arbor


def edge_counts(quads):
    """Each undirected edge of the quads with the number of quads that use it, and the directed edges."""
    directed = np.stack([quads, np.roll(quads, -1, axis=1)], axis=2).reshape(-1, 2).astype(np.int64)
    undirected = np.sort(directed, axis=1)
    _, counts = np.unique(undirected, axis=0, return_counts=True)
    return counts, directed


def assert_closed_mesh(mesh):
    quads = mesh.quads
    assert quads.dtype == np.uint32 and quads.ndim == 2 and quads.shape[1] == 4 and len(quads) > 0
    assert int(quads.max()) < mesh.vertex_count
    assert mesh.quad_count == len(quads)
    counts, directed = edge_counts(quads)
    assert np.all(counts == 2), f"{np.sum(counts != 2)} edges not in exactly two quads"
    # Consistently oriented: the two quads at an edge run along it in opposite directions.
    assert len(np.unique(directed, axis=0)) == len(directed)
    # No quad repeats a vertex.
    assert all(len(set(q)) == 4 for q in quads[:: max(1, len(quads) // 500)].tolist())


def test_presets_are_the_asset_files():
    names = arbor.presets()
    assets = pathlib.Path(arbor.asset_dir())
    files = sorted(p.stem for p in (assets / "presets").glob("*.json"))
    assert files and names[: len(files)] == files
    assert "black-tupelo" in names
    assert all(isinstance(n, str) for n in names)


def test_assets_env_override(monkeypatch, tmp_path):
    palm = arbor.grow("palm", levels=1).parameters
    monkeypatch.setenv("ARBOR_ASSETS", str(tmp_path))
    with pytest.raises(arbor.InputError, match="ARBOR_ASSETS.*presets"):
        arbor.presets()
    (tmp_path / "presets").mkdir()
    (tmp_path / "presets" / "mine.json").write_text(json.dumps(palm))
    assert arbor.presets() == ["mine"]
    assert arbor.grow("mine", levels=1).name == "Palm"


def test_same_seed_same_arrays_other_seed_other_tree():
    a = arbor.grow("black-tupelo", seed=5, levels=2)
    b = arbor.grow("black-tupelo", seed=5, levels=2)
    c = arbor.grow("black-tupelo", seed=6, levels=2)
    assert a.seed == 5 and a.levels == 2 and a.model == "weber-penn" and a.name == "Black Tupelo"
    for key, value in a.skeleton.items():
        assert np.array_equal(value, b.skeleton[key]), key
    for key, value in a.leaves.items():
        assert np.array_equal(value, b.leaves[key]), key
    ma, mb = a.mesh(), b.mesh()
    assert np.array_equal(ma.positions, mb.positions) and np.array_equal(ma.quads, mb.quads)
    sa, sc = a.skeleton["position"], c.skeleton["position"]
    assert sa.shape != sc.shape or not np.array_equal(sa, sc)


def test_skeleton_arrays(small_tree):
    s = small_tree.skeleton
    n = len(s["position"])
    assert n > 100
    assert s["position"].shape == (n, 3) and s["position"].dtype == np.float64
    assert s["direction"].shape == (n, 3)
    for key, dtype in [("radius", np.float64), ("parent", np.int32), ("stem", np.int32), ("level", np.int32), ("kind", np.uint8)]:
        assert s[key].shape == (n,) and s[key].dtype == dtype, key
    assert s["parent"][0] == -1 and np.all((s["parent"][1:] >= 0) & (s["parent"][1:] < n))
    assert np.all(s["radius"] >= 0) and s["radius"][0] > 0 and s["radius"][0] == s["radius"].max()
    assert set(np.unique(s["level"])) == {0, 1}
    assert int(s["kind"].max()) < len(arbor.NODE_KINDS)
    # z up, the trunk base at the origin
    assert np.allclose(s["position"][0], 0.0) and s["position"][:, 2].max() > 1.0


def test_mesh_is_closed_and_in_range(small_tree):
    mesh = small_tree.mesh()
    v = mesh.vertex_count
    assert mesh.positions.shape == (v, 3) and mesh.positions.dtype == np.float32
    for key in ("normals", "tangents", "uvw"):
        assert getattr(mesh, key).shape == (v, 3) and getattr(mesh, key).dtype == np.float32, key
    assert mesh.radius.shape == (v,) and mesh.radius.dtype == np.float32
    assert mesh.level.shape == (v,) and mesh.level.dtype == np.uint8
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-4)
    assert_closed_mesh(mesh)
    assert not mesh.positions.flags.writeable  # a view of the mesh the object holds
    tris = mesh.triangles()
    assert tris.shape == (2 * mesh.quad_count, 3)


@pytest.mark.parametrize("preset", ["sc-sculpted-crown", "fig-1-24f"])
def test_other_growth_models_mesh_closed(preset):
    tree = arbor.grow(preset, seed=2)
    assert tree.model in ("space-colonization", "l-system")
    assert_closed_mesh(tree.mesh())


def test_mesh_levels_and_subdivision(small_tree):
    whole, trunk = small_tree.mesh(), small_tree.mesh(levels=1)
    assert trunk.quad_count < whole.quad_count and int(trunk.level.max()) == 0
    smooth = small_tree.mesh(subdivide=1)
    assert smooth.subdivisions == 1 and smooth.quad_count == 4 * whole.quad_count
    assert_closed_mesh(smooth)


def test_leaves(small_tree):
    leaves = small_tree.leaves
    n = len(leaves["position"])
    assert n > 0
    for key in ("position", "direction", "normal"):
        assert leaves[key].shape == (n, 3) and leaves[key].dtype == np.float64, key
    for key in ("length", "width"):
        assert leaves[key].shape == (n,) and np.all(leaves[key] > 0), key
    assert leaves["kind"].dtype == np.uint8 and int(leaves["kind"].max()) < len(arbor.LEAF_KINDS)
    assert np.allclose(np.linalg.norm(leaves["normal"], axis=1), 1.0, atol=1e-9)
    assert np.allclose(np.linalg.norm(leaves["direction"], axis=1), 1.0, atol=1e-9)
    assert np.allclose(np.sum(leaves["normal"] * leaves["direction"], axis=1), 0.0, atol=1e-9)


def test_export_obj(small_tree, tmp_path):
    mesh = small_tree.mesh()
    path = tmp_path / "tree.obj"
    # The whole tree as generate writes it: the bark, then one card per leaf, with its .mtl and textures.
    small_tree.export(str(path))
    lines = path.read_text().splitlines()
    assert "mtllib tree.mtl" in lines and "o leaves" in lines
    faces = [line for line in lines if line.startswith("f ")]
    assert len(faces) == mesh.quad_count + len(small_tree.leaves["position"])
    for name in ("tree.mtl", "tree_bark_color.png", "tree_bark_normal.png", "tree_leaf_atlas.png"):
        assert (tmp_path / name).stat().st_size > 100, name
    # The bark alone.
    small_tree.export(str(path), leaves=False, cards=False, textures=False)
    lines = path.read_text().splitlines()
    faces = [line for line in lines if line.startswith("f ")]
    assert len(faces) == mesh.quad_count
    assert all(len(f.split()) == 5 for f in faces)  # quads
    assert sum(line.startswith("v ") for line in lines) == mesh.vertex_count
    # Y up by default (as Blender imports OBJ); z keeps Arbor's axes.
    v = np.array([line.split()[1:4] for line in lines if line.startswith("v ")], dtype=np.float64)
    assert np.allclose(v[:, 1], mesh.positions[:, 2], atol=1e-5)
    small_tree.export(str(path), up="z", leaves=False, cards=False, textures=False)
    v = np.array([line.split()[1:4] for line in path.read_text().splitlines() if line.startswith("v ")], dtype=np.float64)
    assert np.allclose(v, mesh.positions, atol=1e-5)


def test_export_glb_and_gltf(small_tree, tmp_path):
    glb = tmp_path / "tree.glb"
    small_tree.export(glb)  # os.PathLike works too
    data = glb.read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    chunk_length, chunk_type = struct.unpack_from("<II", data, 12)
    assert chunk_type == 0x4E4F534A  # JSON
    document = json.loads(data[20 : 20 + chunk_length])
    mesh = small_tree.mesh()
    indices = document["accessors"][document["meshes"][0]["primitives"][0]["indices"]]
    assert indices["count"] == 6 * mesh.quad_count
    assert {m["name"] for m in document["materials"]} == {"bark", "leaves"}
    assert len(document["images"]) == 3
    gltf = tmp_path / "tree.gltf"
    small_tree.export(str(gltf), subdivide=1, lods=2)
    document = json.loads(gltf.read_text())
    assert document["asset"]["version"] == "2.0"
    assert document["nodes"][0]["extensions"]["MSFT_lod"]["ids"] == [1]
    with pytest.raises(arbor.InputError, match="lods"):
        small_tree.export(str(tmp_path / "x.obj"), lods=2)
    assert not list(tmp_path.glob("*.partial-*"))


def test_skeleton_file_round_trip(small_tree, tmp_path):
    path = tmp_path / "tupelo.json"
    small_tree.export(str(path))
    again = arbor.grow(str(path), seed=99)  # a skeleton file is the same tree for any seed
    assert again.model is None and again.parameters is None and again.seed == small_tree.seed
    assert np.array_equal(again.skeleton["position"], small_tree.skeleton["position"])
    assert np.array_equal(again.mesh().quads, small_tree.mesh().quads)


def test_dict_of_parameters_grows_a_tree(small_tree):
    params = small_tree.parameters
    assert isinstance(params, dict) and params["Name"] == "Black Tupelo"
    same = arbor.grow(params, seed=1, levels=2)
    assert np.array_equal(same.skeleton["position"], small_tree.skeleton["position"])
    params = dict(params, Name="Tall tupelo", Scale=params["Scale"] * 2)
    tall = arbor.grow(params, seed=1, levels=2)
    assert tall.name == "Tall tupelo"
    assert tall.skeleton["position"][:, 2].max() > 1.5 * small_tree.skeleton["position"][:, 2].max()
    assert_closed_mesh(tall.mesh())


def test_files_as_sources(data_dir):
    preset = pathlib.Path(arbor.asset_dir()) / "presets" / "palm.json"
    by_path = arbor.grow(preset, levels=1)
    by_name = arbor.grow("palm", levels=1)
    assert np.array_equal(by_path.skeleton["position"], by_name.skeleton["position"])
    shrub = arbor.grow(str(data_dir / "small-arbaro.xml"))
    assert shrub.name == "test_shrub" and shrub.model == "weber-penn"
    assert_closed_mesh(shrub.mesh())


def test_bad_parameter_names_the_field(small_tree):
    params = dict(small_tree.parameters, Levels=99)
    with pytest.raises(ValueError, match="Levels") as caught:
        arbor.grow(params)
    assert isinstance(caught.value, arbor.InputError)
    assert caught.value.field == "Levels" and "allowed" in str(caught.value)
    with pytest.raises(arbor.InputError, match="'Bogus': unknown field"):
        arbor.grow(dict(small_tree.parameters, Bogus=1))
    with pytest.raises(arbor.InputError, match="'model': 'oak' is not a growth model; allowed"):
        arbor.grow({"model": "oak"})


def test_bad_sources_and_arguments(tmp_path, small_tree):
    with pytest.raises(FileNotFoundError, match="no such file"):
        arbor.grow(str(tmp_path / "missing.json"))
    with pytest.raises(ValueError, match="did you mean 'black-tupelo'.*presets: .*palm"):
        arbor.grow("black-tupleo")
    broken = tmp_path / "broken.json"
    broken.write_text('{"Name": "x", "Levels": ')
    with pytest.raises(arbor.InputError, match="broken.json"):
        arbor.grow(str(broken))
    with pytest.raises(arbor.InputError, match="'seed'.*allowed 0"):
        arbor.grow("palm", seed=-3)
    with pytest.raises(arbor.InputError, match="'levels': is 9"):
        arbor.grow("palm", levels=9)
    with pytest.raises(TypeError):
        arbor.grow(42)
    with pytest.raises(arbor.InputError, match="'subdivide': is 7"):
        small_tree.mesh(subdivide=7)
    with pytest.raises(arbor.InputError, match=r"\.obj, \.gltf or \.glb"):
        small_tree.export(str(tmp_path / "tree.stl"))
    with pytest.raises(arbor.InputError, match="'up'"):
        small_tree.export(str(tmp_path / "tree.glb"), up="z")
    with pytest.raises(OSError, match="cannot be written"):
        small_tree.export(str(tmp_path / "no" / "such" / "folder.obj"))
    assert not (tmp_path / "tree.stl").exists() and not (tmp_path / "tree.glb").exists()


def test_export_wind_animation(small_tree, tmp_path):
    glb = tmp_path / "windy.glb"
    small_tree.export(glb, wind=1.0, wind_frames=6, textures=False)
    data = glb.read_bytes()
    chunk_length, _ = struct.unpack_from("<II", data, 12)
    document = json.loads(data[20 : 20 + chunk_length])
    assert document["animations"][0]["name"] == "wind"
    for primitive in document["meshes"][0]["primitives"]:
        assert len(primitive["targets"]) == 6
    with pytest.raises(arbor.InputError, match="wind"):
        small_tree.export(str(tmp_path / "x.obj"), wind=1.0)
    with pytest.raises(arbor.InputError, match="wind_frames"):
        small_tree.export(str(tmp_path / "x.glb"), wind=1.0, wind_frames=2)
