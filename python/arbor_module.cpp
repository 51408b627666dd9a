// The `arbor` Python module: grow a tree from a preset, a file or a dict of parameters, and read its skeleton,
// leaves and quad mesh as numpy arrays, or export it. Everything heavy runs with the GIL released; every C++
// refusal becomes a Python exception carrying the InputError's message (file, field, what is allowed).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/text_util.hpp"
#include "export/subdivide.hpp"
#include "growth/weber_penn/species.hpp"
#include "tree/build_tree.hpp"
#include "tree_io.hpp"

namespace py = pybind11;

namespace arbor::python {

namespace {

// Limits the CLI puts on the same numbers (generate --levels, --mesh-levels, --subdivide).
constexpr int kMaxLevels = 8;
constexpr int kMaxSubdivide = 6;

void requireRange(const char* function, const char* field, int value, int lo, int hi, const char* meaning) {
  if (value < lo || value > hi) {
    throw InputError(function, field, "is " + std::to_string(value) + "; allowed " + std::to_string(lo) + " (" + meaning + ") to " + std::to_string(hi));
  }
}

Up upAxis(const std::string& path, const std::string& up) {
  if (up != "y" && up != "z") throw InputError(path, "up", "is '" + up + "'; allowed 'y' (as Blender imports OBJ) or 'z' (Arbor's own axes)");
  if (!isSkeletonFile(path) && !isMeshFile(path)) {
    throw InputError(path, "path", "a tree is written as .obj, .gltf or .glb (the mesh) or .json (the skeleton)");
  }
  if (up != "y" && !endsWith(path, ".obj")) {
    throw InputError(path, "up", "applies to .obj only (glTF is y up by its specification)");
  }
  return up == "z" ? Up::Z : Up::Y;
}

// A read-only numpy view of `count` rows of `columns` values of T starting at `data`, kept alive by `owner`.
template <class T>
py::array view(const void* data, std::size_t count, std::size_t columns, std::size_t rowBytes, py::handle owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)}, strides{static_cast<py::ssize_t>(rowBytes)};
  if (columns > 0) {
    shape.push_back(static_cast<py::ssize_t>(columns));
    strides.push_back(static_cast<py::ssize_t>(sizeof(T)));
  }
  py::array out(py::dtype::of<T>(), shape, strides, static_cast<const T*>(data), owner);
  out.attr("setflags")(py::arg("write") = false);
  return out;
}

template <class T, class V>
py::array rowsView(const std::vector<V>& rows, std::size_t columns, py::handle owner) {
  static_assert(sizeof(V) % sizeof(T) == 0);
  return view<T>(rows.data(), rows.size(), columns, sizeof(V), owner);
}

// New arrays filled from records: (n, 3) float64 from vectors, (n,) of T from scalars.
template <class Record, class Get>
py::array_t<double> vectors(const std::vector<Record>& records, Get get) {
  py::array_t<double> out({static_cast<py::ssize_t>(records.size()), py::ssize_t{3}});
  auto a = out.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const Vec3 v = get(records[i]);
    for (py::ssize_t k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = v[static_cast<int>(k)];
  }
  return out;
}

template <class T, class Record, class Get>
py::array_t<T> scalars(const std::vector<Record>& records, Get get) {
  py::array_t<T> out(static_cast<py::ssize_t>(records.size()));
  auto a = out.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < records.size(); ++i) a(static_cast<py::ssize_t>(i)) = static_cast<T>(get(records[i]));
  return out;
}

// A file that could not be written (Python: OSError); the message names the path and the reason.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `write` without the GIL; a file that cannot be written (writeFileAtomically: the folder is missing,
// the disk full, ...) is a WriteError.
template <class Write>
void writeFile(Write write) {
  py::gil_scoped_release release;
  try {
    write();
  } catch (const InputError&) {
    throw;
  } catch (const LimitError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw WriteError(e.what());
  }
}

struct Mesh {
  QuadMesh mesh;
  std::string name;
  int subdivisions = 0;

  void write(const std::string& path, const std::string& up) const {
    const Up axis = upAxis(path, up);
    writeFile([&] { writeMeshFile(path, mesh, name, MeshFileOptions{false, axis}, "path"); });
  }
};

struct Tree {
  std::string name;
  std::optional<std::string> model;       // the growth model's name; none for a skeleton or graph file
  std::optional<std::string> parameters;  // the model file, every parameter written
  ImportNotes notes;
  Skeleton skeleton;

  Mesh mesh(int levels, int subdivisions) const {
    requireRange("Tree.mesh", "levels", levels, 0, kMaxLevels, "all levels");
    requireRange("Tree.mesh", "subdivide", subdivisions, 0, kMaxSubdivide, "the control mesh");
    Mesh out{{}, name, subdivisions};
    py::gil_scoped_release release;
    BuildOptions options;
    options.mesh.levels = levels;
    options.patches = false;
    out.mesh = std::move(buildTree(skeleton, options).mesh.mesh);
    if (subdivisions > 0) out.mesh = subdivide(out.mesh, subdivisions);
    return out;
  }
};

// A path argument: a str, or any os.PathLike (pathlib.Path) decoded as os.fsdecode does.
std::string pathArgument(const py::object& path, const char* function) {
  if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  if (!py::hasattr(path, "__fspath__")) {
    throw py::type_error(std::string(function) + ": expected a path (str or os.PathLike), not " +
                         std::string(py::str(py::type::of(path).attr("__name__"))));
  }
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
}

std::uint64_t seedValue(const py::int_& seed) {
  const unsigned long long value = PyLong_AsUnsignedLongLong(seed.ptr());
  if (value == static_cast<unsigned long long>(-1) && PyErr_Occurred()) {
    PyErr_Clear();
    throw InputError("arbor.grow", "seed", "is " + std::string(py::str(py::handle(seed))) + "; allowed 0 to 18446744073709551615");
  }
  return value;
}

Tree grow(const py::object& source, const py::int_& seed, int levels) {
  Tree tree;
  const std::uint64_t seedNumber = seedValue(seed);
  requireRange("arbor.grow", "levels", levels, 0, kMaxLevels, "the model's own");
  std::optional<TreeSource> loaded;
  if (py::isinstance<py::dict>(source)) {
    const std::string json = py::module_::import("json").attr("dumps")(source, py::arg("allow_nan") = false).cast<std::string>();
    py::gil_scoped_release release;
    loaded.emplace(sourceFromJson(json, "parameters (dict)", &tree.notes));
  } else {
    if (!py::isinstance<py::str>(source) && !py::hasattr(source, "__fspath__")) {
      throw py::type_error("arbor.grow: source must be a preset name, a path or a dict of model parameters, not " +
                           std::string(py::str(py::type::of(source).attr("__name__"))));
    }
    const std::string name = pathArgument(source, "arbor.grow");
    py::gil_scoped_release release;
    loaded.emplace(loadSource(name, &tree.notes));
  }
  tree.name = loaded->name();
  if (const TreeModel* model = loaded->model()) {
    tree.model = model->model();
    tree.parameters = model->toJson();
  }
  py::gil_scoped_release release;
  GrowthOptions options;
  options.seed = seedNumber;
  options.levels = levels;
  tree.skeleton = loaded->grow(options);
  return tree;
}

std::vector<std::string> leafKindNames() {
  std::vector<std::string> names(4);
  names[static_cast<std::size_t>(LeafKind::Broad)] = "broad";
  names[static_cast<std::size_t>(LeafKind::Narrow)] = "narrow";
  names[static_cast<std::size_t>(LeafKind::Frond)] = "frond";
  names[static_cast<std::size_t>(LeafKind::Needle)] = "needle";
  return names;
}

std::vector<std::string> nodeKindNames() {
  std::vector<std::string> names;
  for (int k = 0; k <= static_cast<int>(NodeKind::Tip); ++k) names.emplace_back(nodeKindName(static_cast<NodeKind>(k)));
  return names;
}

// C++ refusals as Python exceptions: a missing path is FileNotFoundError, other bad input arbor.InputError
// (a ValueError with .file and .field), a tree past the size limits arbor.LimitError (a ValueError).
void registerExceptions(py::module_& m) {
  static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<LimitError> limitError(m, "LimitError", PyExc_ValueError);
  inputError.doc() = "Input Arbor refuses: the message names the file (or function), the field and what is allowed. "
                     "A ValueError; .file and .field hold the first two.";
  limitError.doc() = "A tree, mesh or subdivision past Arbor's size limits; the message says which parameters drive it. A ValueError.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const MissingFile& e) {
      // The message names the path already; OSError's "[Errno 2] ...: 'path'" form would say it twice.
      py::object error = py::reinterpret_borrow<py::object>(PyExc_FileNotFoundError)(e.what());
      error.attr("errno") = ENOENT;
      PyErr_SetObject(PyExc_FileNotFoundError, error.ptr());
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(inputError.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("field") = e.field();
      PyErr_SetObject(inputError.ptr(), error.ptr());
    } catch (const LimitError& e) {
      PyErr_SetString(limitError.ptr(), e.what());
    } catch (const WriteError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
}

}  // namespace

}  // namespace arbor::python

PYBIND11_MODULE(arbor, m) {
  using namespace arbor;
  using namespace arbor::python;
  m.doc() = R"(Arbor's trees from Python: grow any growth model (Weber-Penn, L-systems, space colonization) from a
preset, a file or a dict of parameters; read the skeleton, the leaves and the closed quad mesh as numpy arrays;
export OBJ, glTF or GLB. Coordinates are metres, z up (as Blender), the trunk base at the origin.

    import arbor
    tree = arbor.grow("black-tupelo", seed=7, levels=2)
    mesh = tree.mesh(subdivide=1)
    mesh.positions.shape, mesh.quads.shape   # (V, 3) float32, (Q, 4) uint32
    tree.export("tupelo.glb")
)";
  m.attr("__version__") = ARBOR_VERSION;
  m.attr("LEAF_KINDS") = leafKindNames();
  m.attr("NODE_KINDS") = nodeKindNames();
  registerExceptions(m);

  m.def("asset_dir", &assetDirectory,
        "The assets folder (presets/, lsystems/, textures/): $ARBOR_ASSETS when set, else the source tree's assets/ "
        "the module was built from. Raises arbor.InputError when it has no presets/.");
  m.def("presets", &presetNames,
        "Preset names, as `arbor species --list` prints them: the model files in assets/presets (*.json), then the "
        "L-system grammars in assets/lsystems (*.lsys), each group sorted. Any of them is a `source` for grow().");

  py::class_<Mesh>(m, "Mesh", R"(One closed quad mesh (every edge in exactly two quads, counter-clockwise seen from outside), in
metres, z up. The arrays are read-only views of the mesh held by this object (copy them to edit):
positions, normals, tangents (V, 3) float32; uvw (V, 3) float32 (u mirrored 0..1 around the branch, v along
it, w the flip coordinate); radius (V,) float32; level (V,) uint8; quads (Q, 4) uint32.)")
      .def_property_readonly("positions", [](py::object self) { return rowsView<float>(self.cast<const Mesh&>().mesh.positions, 3, self); },
                             "(V, 3) float32 vertex positions in metres, z up.")
      .def_property_readonly("normals", [](py::object self) { return rowsView<float>(self.cast<const Mesh&>().mesh.normals, 3, self); },
                             "(V, 3) float32 unit normals, area-weighted from the quads around each vertex (the limit surface's "
                             "after subdivision).")
      .def_property_readonly("tangents", [](py::object self) { return rowsView<float>(self.cast<const Mesh&>().mesh.tangents, 3, self); },
                             "(V, 3) float32 unit tangents along the branch (the direction of increasing v).")
      .def_property_readonly("uvw", [](py::object self) { return rowsView<float>(self.cast<const Mesh&>().mesh.uvw, 3, self); },
                             "(V, 3) float32 texture coordinates: u mirrored 0..1 front to back, v along the branch, w the flip "
                             "coordinate (bark u is 0.5 u where w >= 0, else 1 - 0.5 u: no texture seams).")
      .def_property_readonly("radius", [](py::object self) { return rowsView<float>(self.cast<const Mesh&>().mesh.radius, 0, self); },
                             "(V,) float32 branch radius each vertex was placed for, in metres.")
      .def_property_readonly("level", [](py::object self) { return rowsView<std::uint8_t>(self.cast<const Mesh&>().mesh.level, 0, self); },
                             "(V,) uint8 stem level of each vertex (0: trunk).")
      .def_property_readonly("quads", [](py::object self) { return rowsView<std::uint32_t>(self.cast<const Mesh&>().mesh.quads, 4, self); },
                             "(Q, 4) uint32 vertex indices of each quad, counter-clockwise seen from outside.")
      .def("triangles", [](const Mesh& self) {
            const std::vector<std::array<std::uint32_t, 3>> tris = triangulate(self.mesh);
            py::array_t<std::uint32_t> out({static_cast<py::ssize_t>(tris.size()), py::ssize_t{3}});
            if (!tris.empty()) std::memcpy(out.mutable_data(), tris.data(), tris.size() * sizeof(tris[0]));
            return out;
          },
          "(2Q, 3) uint32: each quad split along its shorter diagonal, keeping the outward orientation.")
      .def_property_readonly("vertex_count", [](const Mesh& self) { return self.mesh.positions.size(); })
      .def_property_readonly("quad_count", [](const Mesh& self) { return self.mesh.quads.size(); })
      .def_readonly("subdivisions", &Mesh::subdivisions, "Catmull-Clark levels applied (0: the control mesh).")
      .def("export", [](const Mesh& self, const py::object& path, const std::string& up) { self.write(pathArgument(path, "Mesh.export"), up); },
           py::arg("path"), py::arg("up") = "y",
           "Writes this mesh as the file `path` names: .obj (quads; `up` 'y' as Blender imports OBJ, or 'z'), .gltf or "
           ".glb (triangles, y up). Written whole or not at all.")
      .def("__repr__", [](const Mesh& self) {
        return "<arbor.Mesh " + std::to_string(self.mesh.quads.size()) + " quads, " + std::to_string(self.mesh.positions.size()) +
               " vertices, " + std::to_string(self.subdivisions) + " subdivisions>";
      });

  py::class_<Tree>(m, "Tree", "A grown tree: its skeleton and leaves, meshed on request. Made by arbor.grow().")
      .def_readonly("name", &Tree::name, "The tree's name (the species, or the skeleton or graph file's).")
      .def_readonly("model", &Tree::model, "The growth model ('weber-penn', 'l-system', 'space-colonization'); None for a skeleton or graph file.")
      .def_property_readonly("seed", [](const Tree& t) { return t.skeleton.seed; },
                             "The seed it grew for (a skeleton or graph file: the seed its file records).")
      .def_property_readonly("levels", [](const Tree& t) { return t.skeleton.levels; }, "Stem levels grown.")
      .def_property_readonly("parameters", [](const Tree& t) -> py::object {
            if (!t.parameters) return py::none();
            return py::module_::import("json").attr("loads")(*t.parameters);
          },
          "The model's parameters as a dict (every one written, as its model file has them): edit and pass to "
          "arbor.grow(). None for a skeleton or graph file.")
      .def_property_readonly("notes", [](const Tree& t) {
            py::dict out;
            out["defaulted"] = t.notes.defaulted;
            out["ignored"] = t.notes.ignored;
            return out;
          },
          "What reading the source noticed: {'defaulted': parameters absent that took defaults, 'ignored': read but unused}.")
      .def_property_readonly("skeleton", [](const Tree& t) {
            const std::vector<SkeletonNode>& n = t.skeleton.nodes;
            py::dict out;
            out["position"] = vectors(n, [](const SkeletonNode& s) { return s.world.position; });
            out["direction"] = vectors(n, [](const SkeletonNode& s) { return s.world.direction(); });
            out["radius"] = scalars<double>(n, [](const SkeletonNode& s) { return s.radius; });
            out["parent"] = scalars<std::int32_t>(n, [](const SkeletonNode& s) { return s.parent; });
            out["stem"] = scalars<std::int32_t>(n, [](const SkeletonNode& s) { return s.stem; });
            out["level"] = scalars<std::int32_t>(n, [](const SkeletonNode& s) { return s.level; });
            out["kind"] = scalars<std::uint8_t>(n, [](const SkeletonNode& s) { return static_cast<int>(s.kind); });
            return out;
          },
          "The skeleton's nodes as a dict of new numpy arrays, one row per node: position (N, 3) float64 in metres; "
          "direction (N, 3) float64, the unit direction of the stem leaving the node; radius (N,) float64; parent (N,) "
          "int32 (-1 for the root); stem (N,) int32; level (N,) int32 (0: trunk); kind (N,) uint8, an index into "
          "arbor.NODE_KINDS.")
      .def_property_readonly("leaves", [](const Tree& t) {
            const std::vector<Leaf>& l = t.skeleton.leaves;
            py::dict out;
            out["position"] = vectors(l, [](const Leaf& x) { return x.position; });
            out["direction"] = vectors(l, [](const Leaf& x) { return x.direction; });
            out["normal"] = vectors(l, [](const Leaf& x) { return x.normal; });
            out["length"] = scalars<double>(l, [](const Leaf& x) { return x.length; });
            out["width"] = scalars<double>(l, [](const Leaf& x) { return x.width; });
            out["kind"] = scalars<std::uint8_t>(l, [](const Leaf& x) { return x.kind; });
            out["stem"] = scalars<std::int32_t>(l, [](const Leaf& x) { return x.stem; });
            out["node"] = scalars<std::int32_t>(l, [](const Leaf& x) { return x.node; });
            return out;
          },
          "The leaves as a dict of new numpy arrays, one row per leaf: position (L, 3) float64, the base of the blade; "
          "direction (L, 3), unit, base to tip; normal (L, 3), the blade's unit face normal; length and width (L,) "
          "float64 in metres; kind (L,) uint8, an index into arbor.LEAF_KINDS (the leaf atlas's cell); stem and node "
          "(L,) int32 it hangs from.")
      .def("mesh", &Tree::mesh, py::arg("levels") = 0, py::arg("subdivide") = 0,
           "The tree as one closed quad mesh (arbor.Mesh). levels: mesh only stems of levels below this (0: all, up to "
           "8); subdivide: Catmull-Clark levels by OpenSubdiv (0 to 6, quads times 4 each), positions on the limit "
           "surface.")
      .def("export", [](const Tree& t, const py::object& pathObject, int levels, int subdivisions, const std::string& up, bool leaves,
                        bool cards, bool textures, int lods, double wind, double windAzimuth, double gustFrequency, int windFrames) {
            const std::string path = pathArgument(pathObject, "Tree.export");
            if (isSkeletonFile(path)) {
              if (levels != 0 || subdivisions != 0 || up != "y" || lods != 1) {
                throw InputError(path, "path", "levels, subdivide, up and lods apply to meshes (.obj, .gltf, .glb), not to a skeleton (.json)");
              }
              writeFile([&] { writeSkeletonFile(path, t.skeleton); });
              return;
            }
            const Up axis = upAxis(path, up);  // refused before any meshing
            requireRange("Tree.export", "levels", levels, 0, kMaxLevels, "all levels");
            requireRange("Tree.export", "subdivide", subdivisions, 0, kMaxSubdivide, "the control mesh");
            requireRange("Tree.export", "lods", lods, 1, kMaxLevels, "the finest only");
            if (lods > 1 && endsWith(path, ".obj")) throw InputError(path, "lods", "an OBJ holds one level of detail; levels of detail need .gltf or .glb");
            if (!(wind >= 0.0 && wind <= 4.0)) throw InputError("Tree.export", "wind", "is " + std::to_string(wind) + "; allowed 0 (none) to 4");
            if (!(gustFrequency >= 0.02 && gustFrequency <= 4.0))
              throw InputError("Tree.export", "gust_frequency", "is " + std::to_string(gustFrequency) + "; allowed 0.02 to 4 gusts per second");
            if (!std::isfinite(windAzimuth)) throw InputError("Tree.export", "wind_azimuth", "must be a finite number of degrees");
            requireRange("Tree.export", "wind_frames", windFrames, 4, 120, "the fewest keyframes");
            if (wind > 0.0 && endsWith(path, ".obj")) throw InputError(path, "wind", "an OBJ cannot hold an animation; the wind animation needs .gltf or .glb");
            TreeFileOptions options;
            options.file = MeshFileOptions{false, axis};
            options.asset.mesh.levels = levels;
            options.asset.subdivide = subdivisions;
            options.asset.lods = lods;
            options.asset.leaves = leaves;
            options.asset.branchCards = cards;
            options.textures = textures;
            options.asset.wind.strength = wind;
            options.asset.wind.azimuth = windAzimuth;
            options.asset.wind.gustFrequency = gustFrequency;
            options.asset.windFrames = windFrames;
            writeFile([&] { writeTreeFile(path, t.skeleton, t.name, options, nullptr, {}, "path"); });
          },
          py::arg("path"), py::arg("levels") = 0, py::arg("subdivide") = 0, py::arg("up") = "y", py::kw_only(), py::arg("leaves") = true,
          py::arg("cards") = true, py::arg("textures") = true, py::arg("lods") = 1, py::arg("wind") = 0.0, py::arg("wind_azimuth") = 0.0,
          py::arg("gust_frequency") = 0.25, py::arg("wind_frames") = 24,
          "Writes the tree as the file `path` names, as `arbor generate` does (docs/export.md): .obj (quads; `up` 'y' as "
          "Blender imports OBJ, or 'z'; a .mtl and PNG textures beside it), .gltf or .glb (triangles, y up, textures "
          "inside, `lods` levels of detail by MSFT_lod; `wind` > 0: a looping wind animation of `wind_frames` morph "
          "targets, docs/wind.md); the bark meshed as mesh(levels, subdivide), with leaf cards "
          "(`leaves`), fake-branch cards for stem levels not meshed (`cards`) and textures (`textures`); or .json, the "
          "skeleton (arbor-skeleton/1, which grow() reads back as the same tree). Written whole or not at all.")
      .def("__repr__", [](const Tree& t) {
        return "<arbor.Tree '" + t.name + "' seed " + std::to_string(t.skeleton.seed) + ", " + std::to_string(t.skeleton.levels) + " levels, " +
               std::to_string(t.skeleton.nodes.size()) + " nodes, " + std::to_string(t.skeleton.leaves.size()) + " leaves>";
      });

  m.def("grow", &grow, py::arg("source"), py::arg("seed") = 1, py::arg("levels") = 0,
        R"(Grows a tree (arbor.Tree).

source: a preset name (arbor.presets()); a path (str or os.PathLike) to a model file (.json of any growth
  model, an Arbaro .xml species, an .lsys grammar) or to a tree given whole (an arbor-skeleton/1 or
  arbor-graph/1 .json: the same tree for any seed); or a dict of model parameters, read as the same JSON a
  model file holds (Tree.parameters gives a preset's, to edit).
seed: 0 to 2**64 - 1; the same seed gives identical arrays.
levels: stem levels to grow, 1 to 8 (0: the model's own).

Raises FileNotFoundError for a path that does not exist, arbor.InputError (a ValueError) naming the file,
field and what is allowed for bad input, arbor.LimitError for a tree past the size limits.)");
}
