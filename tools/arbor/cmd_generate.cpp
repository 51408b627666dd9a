// arbor generate: species parameters in, a tree out (skeleton JSON now; meshes with the mesh stage).
#include <chrono>
#include <cstdio>
#include <future>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "common/text_util.hpp"
#include "growth/skeleton_checks.hpp"
#include "growth/skeleton_json.hpp"
#include "export/subdivide.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/tree_mesh.hpp"
#include "tree/build_tree.hpp"
#include "export_options.hpp"
#include "patches/patch_set.hpp"

namespace arbor::cli {

namespace {

struct GenerateOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species;
  std::uint64_t seed = 1;
  int levels = 0;
  std::string out;
  bool quiet = false;
  MeshOptions mesh;
  ExportChoices exported;
  int subdivide = 0;
};

enum class OutputType { Skeleton, Obj, Gltf, Glb };

OutputType outputType(const std::string& path) {
  if (endsWith(path, ".json")) return OutputType::Skeleton;
  if (endsWith(path, ".obj")) return OutputType::Obj;
  if (endsWith(path, ".gltf")) return OutputType::Gltf;
  if (endsWith(path, ".glb")) return OutputType::Glb;
  throw InputError(path, "--out", "unsupported output type; allowed: .json (skeleton), .obj, .gltf, .glb (mesh)");
}

void printNotes(const std::string& species, const ImportNotes& notes) {
  if (!notes.defaulted.empty()) {
    std::string list;
    for (const std::string& d : notes.defaulted) list += (list.empty() ? "" : ", ") + d;
    std::fprintf(stderr, "arbor: note: %s: %zu parameters absent from the file took Arbaro defaults: %s\n",
                 species.c_str(), notes.defaulted.size(), list.c_str());
  }
  if (!notes.ignored.empty()) {
    std::string list;
    for (const std::string& d : notes.ignored) list += (list.empty() ? "" : ", ") + d;
    std::fprintf(stderr, "arbor: note: %s: read but not used: %s\n", species.c_str(), list.c_str());
  }
}

int runGenerate(const GenerateOptions& o) {
  const OutputType type = outputType(o.out);
  requireOutputFile(o.out);
  if (type == OutputType::Skeleton && (o.subdivide > 0 || o.exported.triangles || o.exported.lods > 0)) {
    throw InputError(o.out, "--out", "--subdivide, --lods and --triangles apply to meshes (.obj, .gltf, .glb), not to a skeleton");
  }
  if (type == OutputType::Skeleton && o.exported.up != "y") {
    throw InputError(o.out, "--up", "applies to .obj only (glTF is y up by its specification; the skeleton keeps Arbor's z up)");
  }
  MeshOptions mesh = o.mesh;
  mesh.searchBesideMesher = true;  // a one-shot export: nothing draws frames after the build
  const TreeFileOptions fileOptions = type == OutputType::Skeleton ? TreeFileOptions{} : treeFileOptions(o.out, o.exported, mesh, o.subdivide);
  ImportNotes notes;
  const TreeSource source = loadTreeArgument(o.species, &notes, o.angles);
  if (!o.quiet) printNotes(o.species, notes);

  GrowthOptions growth;
  growth.seed = o.seed;
  growth.levels = o.levels;
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const auto t0 = Clock::now();
  const Skeleton skeleton = source.grow(growth);
  const auto t1 = Clock::now();

  const auto shared = std::make_shared<TreeMesh>();  // the export shares it (no copy of a large mesh)
  TreeMesh& tree = *shared;
  double meshMs = 0.0;
  // The summary needs the mesh before the export: then it is built here and shared. Quiet, the export builds it
  // itself while it makes the cards on another core.
  const bool meshHere = !o.quiet && type != OutputType::Skeleton;
  if (meshHere) {
    tree = buildTree(skeleton, BuildOptions{mesh, false}).mesh;  // patches are counted on another core below
    meshMs = ms(t1, Clock::now());
  }
  // The summary's topology and patch counts are worked out on another core while the file is written.
  struct MeshSummary {
    MeshTopologyReport topology;
    PatchSet patches;
  };
  std::future<MeshSummary> summary;
  if (meshHere) {
    summary = std::async(std::launch::async, [&tree] { return MeshSummary{checkTopology(tree.mesh), buildPatches(tree.mesh)}; });
  }
  if (type == OutputType::Skeleton) {
    writeFileAtomically(o.out, [&](std::ostream& out) { writeSkeletonJson(skeleton, out); });
  } else {
    // Levels of detail, subdivision and textures take seconds on large trees: say what is happening.
    auto progress = [&](const std::string& step) {
      if (!o.quiet) std::fprintf(stderr, "arbor generate: %6.0f ms  %s\n", ms(t0, Clock::now()), step.c_str());
    };
    if (o.subdivide > 0) {
      progress("meshed " + std::to_string(tree.mesh.quads.size()) + " quads; subdividing " + std::to_string(o.subdivide) +
               " time(s) (about " + std::to_string(tree.mesh.quads.size() << (2 * o.subdivide)) + " quads at the finest level)");
    }
    writeTreeFile(o.out, skeleton, source.name(), fileOptions, meshHere ? shared : nullptr, progress);
  }
  if (o.quiet) return 0;

  const SkeletonStats stats = skeletonStats(skeleton);
  std::string perLevel;
  for (std::size_t i = 0; i < stats.stemsPerLevel.size(); ++i) {
    perLevel += (i ? ", " : "") + std::to_string(stats.stemsPerLevel[i]);
  }
  std::printf("%s, seed %llu, %d levels: skeleton %s in %.1f ms\n", source.name().c_str(),
              static_cast<unsigned long long>(skeleton.seed), skeleton.levels, source.model() ? "grown" : "from its file", ms(t0, t1));
  std::printf("  stems per level  %s\n", perLevel.c_str());
  std::printf("  nodes            %zu (%zu branch points)\n", stats.nodes, stats.branchPoints);
  std::printf("  leaves           %zu\n", stats.leaves);
  if (stats.stubs > 0) std::printf("  stubs            %zu (too short, stubby or thin for a tube: fake branches, not in the mesh)\n", stats.stubs);
  std::printf("  height           %.2f m, crown radius %.2f m, trunk base radius %.3f m\n", stats.height,
              stats.crownRadius, skeleton.nodes.empty() ? 0.0 : skeleton.nodes.front().radius);
  std::printf("  r^E conservation worst relative error %.1e (E = %.2f)\n", worstConservationError(skeleton),
              skeleton.exponent);
  if (type != OutputType::Skeleton) {
    const MeshSummary counted = summary.get();
    const MeshTopologyReport& topology = counted.topology;
    const PatchSet& patches = counted.patches;
    std::size_t regular = 0, fallback = 0;
    for (PatchKind k : patches.kind) {
      regular += k == PatchKind::Regular ? 1 : 0;
      fallback += k == PatchKind::Fallback ? 1 : 0;
    }
    std::printf("  mesh             %zu quads, %zu vertices in %.1f ms; %zu joints\n", tree.mesh.quads.size(),
                tree.mesh.vertexCount(), meshMs, tree.joints.size());
    if (!tree.fakedStems.empty()) {
      std::printf("  faked stems      %zu (%s)\n", tree.fakedStems.size(), kFakedStemsNote);
    }
    std::printf("  topology         %s, %zu piece(s), Euler characteristic %d, valence %d..%d\n",
                topology.boundaryEdges == 0 && topology.nonManifoldEdges == 0 ? "closed 2-manifold" : "OPEN OR NON-MANIFOLD",
                topology.components, topology.eulerCharacteristic, topology.minValence, topology.maxValence);
    std::printf("  patches          %zu regular, %zu extraordinary, %zu fallback\n", regular,
                patches.size() - regular - fallback, fallback);
    if (o.subdivide > 0) {
      std::printf("  exported         %zu quads after %d Catmull-Clark levels (OpenSubdiv, limit positions)\n",
                  tree.mesh.quads.size() << (2 * o.subdivide), o.subdivide);
    }
  }
  std::printf("wrote %s\n", o.out.c_str());
  return 0;
}

}  // namespace

namespace {

// `generate` and `mesh` are one command: a tree from any source, out as a skeleton or a mesh.
void addOptions(CLI::App* cmd, GenerateOptions& o, const char* input) {
  cmd->add_option("species", o.species, input)->required();
  addAnglesOption(cmd, o.angles);
  cmd->add_option("--seed", o.seed, "Random seed of a growth model; the same seed gives byte-identical output (a skeleton or graph file is the same tree for any seed)")
      ->check(Seed())
      ->capture_default_str();
  cmd->add_option("--levels", o.levels, "Stem levels to grow (default: the model's Levels; a skeleton or graph file keeps its own)")
      ->check(Whole(1, 8));
  cmd->add_option("--out", o.out,
                  "Output file: .json writes the skeleton; .obj (quads; a .mtl and PNG textures beside it), .gltf or .glb "
                  "(triangles with _RADIUS, _LEVEL and _FLIP attributes, textures inside, levels of detail) write the tree "
                  "with its leaf and fake-branch cards")
      ->required();
  cmd->add_option("--ring-spacing", o.mesh.ringSpacing,
                  "Extra cross sections wherever rings are farther apart than this many local radii (0: off)")
      ->check(OffOrNumber(0.01, 1000.0))
      ->capture_default_str();
  cmd->add_option("--max-ring-distance", o.mesh.maxRingDistance,
                  "Extra cross sections wherever rings are farther apart than this many metres (0: off)")
      ->check(OffOrNumber(0.0001, 1000.0))
      ->capture_default_str();
  cmd->add_option("--mesh-levels", o.mesh.levels, "Mesh only stems of levels below this (0: all)")
      ->check(Whole(0, 8));
  cmd->add_flag("--open-base", o.mesh.openBase, "Leave the ring at the trunk base open (closed by default)");
  cmd->add_flag_callback("--mesh-displaced", [&o] { o.mesh.fakeDisplaced = false; },
                         kMeshDisplacedHelp);
  addExportOptions(cmd, o.exported);
  cmd->add_option("--subdivide", o.subdivide, "Export the bark mesh (every level of detail) after N Catmull-Clark levels (OpenSubdiv)")
      ->check(Whole(0, 6));
  cmd->add_flag("--quiet", o.quiet, "Print nothing on success");
}

}  // namespace

void addGenerateCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("generate", "Grow a tree from a preset or model file and write its skeleton or mesh.");
  addOptions(cmd, *o,
             "Preset name (see 'arbor species --list'), a .json model file, an .xml Arbaro species file, or an "
             "arbor-skeleton/1 or arbor-graph/1 .json file");
  cmd->callback([o, &action] { action = [o] { return runGenerate(*o); }; });
}

void addMeshCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = app.add_subcommand("mesh", "Mesh a skeleton or branch graph (any rooted graph of internodes) as one closed quad mesh; "
                                             "also takes what 'generate' takes.");
  addOptions(cmd, *o,
             "An arbor-graph/1 file (docs/graph-format.md) or arbor-skeleton/1 file (docs/skeleton-format.md), "
             "or a preset or model file");
  cmd->callback([o, &action] { action = [o] { return runGenerate(*o); }; });
}

}  // namespace arbor::cli
