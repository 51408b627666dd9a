// arbor check: which quads of a tree's mesh intersect, and whether the skeleton or the mesher made each
// crossing (docs/mesh.md, "Checking a mesh for self-intersections"). Exit 1 when the mesher made any.
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "common/json_writer.hpp"
#include "common/text_util.hpp"
#include "growth/growth_model.hpp"
#include "tree/build_tree.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/tree_mesh.hpp"
#include "obj_quads.hpp"

namespace arbor::cli {

namespace {

struct CheckOptions {
  AngleChoice angles = AngleChoice::File;
  std::string input;
  std::uint64_t seed = 1;
  int levels = 0;
  std::size_t list = 0;
  std::string json;
  bool meshDisplaced = false;  // mesh the children MeshOptions::fakeDisplaced draws as fake branches
};

// What was checked: the mesh, and the skeleton and stems when it was grown here.
struct Checked {
  std::string title;
  TreeMesh tree;
  Skeleton skeleton;
  bool grown = false;
  double buildMs = 0;
};

Checked load(const CheckOptions& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  Checked c;
  if (endsWith(o.input, ".obj")) {
    c.tree.mesh = readObjQuads(o.input);
    c.title = o.input;
  } else {
    const TreeSource source = loadTreeArgument(o.input, nullptr, o.angles);
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    c.skeleton = source.grow(growth);
    MeshOptions mesh;
    mesh.fakeDisplaced = !o.meshDisplaced;
    c.tree = buildTree(c.skeleton, BuildOptions{mesh, false}).mesh;
    c.grown = true;
    c.title = source.name() + ", seed " + std::to_string(c.skeleton.seed) + ", " + std::to_string(c.skeleton.levels) + " levels";
  }
  c.buildMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return c;
}

int stemLevel(const Checked& c, int stem) {
  return stem >= 0 && stem < static_cast<int>(c.skeleton.stems.size()) ? c.skeleton.stems[static_cast<std::size_t>(stem)].level : -1;
}

void printSummary(const Checked& c, const SelfIntersectionReport& r) {
  std::printf("%s: %zu quads (%s in %.1f ms), checked in %.1f ms\n", c.title.c_str(), r.quads,
              c.grown ? "grown and meshed" : "read", c.buildMs, r.milliseconds);
  std::printf("  intersecting pairs  %zu\n", r.pairs);
  if (r.classified) {
    std::printf("  skeleton-made       %zu  (the skeleton's branches cross there: Weber-Penn allows it)\n", r.skeletonMade);
    std::printf("  mesh-made           %zu  (no crossing in the skeleton there: the mesher's doing)\n", r.meshMade);
    std::printf("    at shallow joints %zu  (in the neck or first band of a child leaving its parent at under 34 degrees, whose\n"
                "                       skeleton stays inside the parent past the 1.5 parent radii its first cross section may stand)\n",
                r.meshMadeAtShallowJoints);
  }
  std::printf("  folds               %zu  (pairs sharing an edge)\n", r.folds);
  if (r.classified) {
    std::printf("  neck crossings      %zu  (a child against its own parent, a clone against its source)\n", r.neckCrossings);
    std::printf("    through the parent %zu  (the child's neck or first band; the rest lie farther along the child, where its\n"
                "                       skeleton runs back into its parent or close along it)\n",
                r.necksThroughParent);
    if (!c.tree.fakedStems.empty()) {
      std::printf("  faked stems         %zu  (%s, not checked; --mesh-displaced meshes them)\n", c.tree.fakedStems.size(), kFakedStemsNote);
    }
    // Where the mesher's crossings are, by how the two stems relate and their levels: what to fix first.
    std::map<std::string, std::size_t> where;
    for (const QuadPairHit& h : r.hits) {
      if (h.origin != PairOrigin::Mesh) continue;
      const int la = stemLevel(c, h.stemA), lb = stemLevel(c, h.stemB);
      where[std::string(stemRelationName(h.relation)) + ", levels " + std::to_string(std::min(la, lb)) + "-" +
            std::to_string(std::max(la, lb)) + ", " + quadContactName(h.contact) + " contact"]++;
    }
    for (const auto& [what, count] : where) std::printf("    mesh-made  %6zu  %s\n", count, what.c_str());
  }
}

void printList(const Checked& c, const SelfIntersectionReport& r, std::size_t n) {
  const std::size_t shown = std::min(n, r.hits.size());
  if (shown == 0) return;
  std::printf("  first %zu of %zu pairs (quad/stem/level, quad/stem/level, contact, stems, origin, point, distance from\n"
              "  each stem's skeleton axis in its radii; a neck through its own parent marked so):\n", shown, r.hits.size());
  for (std::size_t i = 0; i < shown; ++i) {
    const QuadPairHit& h = r.hits[i];
    std::printf("    %u/%d/%d  %u/%d/%d  %s  %s  %s  (%.6g, %.6g, %.6g)  %.3g %.3g%s\n", h.a, h.stemA, stemLevel(c, h.stemA),
                h.b, h.stemB, stemLevel(c, h.stemB), quadContactName(h.contact), stemRelationName(h.relation),
                pairOriginName(h.origin), h.point.x, h.point.y, h.point.z, h.reachA, h.reachB,
                h.throughParent ? "  neck through its parent" : "");
  }
}

void writeJson(const std::string& path, const CheckOptions& o, const Checked& c, const SelfIntersectionReport& r) {
  writeFileAtomically(path, [&](std::ostream& out) {
    JsonWriter w;
    w.beginObject();
    w.field("input", o.input);
    if (c.grown) w.field("seed", static_cast<std::int64_t>(o.seed)).field("levels", c.skeleton.levels);
    w.field("quads", static_cast<std::int64_t>(r.quads)).field("pairs", static_cast<std::int64_t>(r.pairs));
    w.field("classified", r.classified);
    if (r.classified) {
      w.field("skeletonMade", static_cast<std::int64_t>(r.skeletonMade)).field("meshMade", static_cast<std::int64_t>(r.meshMade));
      w.field("neckCrossings", static_cast<std::int64_t>(r.neckCrossings));
      w.field("necksThroughParent", static_cast<std::int64_t>(r.necksThroughParent));
      w.field("meshMadeAtShallowJoints", static_cast<std::int64_t>(r.meshMadeAtShallowJoints));
      w.field("fakedStems", static_cast<std::int64_t>(c.tree.fakedStems.size()));
    }
    w.field("folds", static_cast<std::int64_t>(r.folds)).field("milliseconds", r.milliseconds);
    w.key("hits").beginArray();
    for (const QuadPairHit& h : r.hits) {
      w.beginObject();
      w.field("a", static_cast<std::int64_t>(h.a)).field("b", static_cast<std::int64_t>(h.b));
      w.field("stemA", h.stemA).field("stemB", h.stemB);
      w.field("levelA", stemLevel(c, h.stemA)).field("levelB", stemLevel(c, h.stemB));
      w.field("contact", quadContactName(h.contact)).field("relation", stemRelationName(h.relation));
      w.field("origin", pairOriginName(h.origin));
      if (r.classified) w.field("reachA", h.reachA).field("reachB", h.reachB).field("shallowJoint", h.shallowJoint).field("throughParent", h.throughParent);
      w.key("point").vec3(h.point.x, h.point.y, h.point.z);
      w.endObject();
      if (w.pending() > (1u << 20)) w.flushTo(out);
    }
    w.endArray();
    w.endObject();
    w.flushTo(out);
    out << '\n';
  });
}

int runCheck(const CheckOptions& o) {
  if (!o.json.empty()) requireOutputFile(o.json, "--json");
  const Checked c = load(o);
  const SelfIntersectionReport r = c.grown ? checkSelfIntersections(c.tree, c.skeleton) : checkSelfIntersections(c.tree.mesh);
  printSummary(c, r);
  printList(c, r, o.list);
  if (!o.json.empty()) {
    writeJson(o.json, o, c, r);
    std::printf("wrote %s\n", o.json.c_str());
  }
  // A bare mesh cannot say who made a crossing: every pair counts against it.
  const std::size_t unexplained = r.classified ? r.meshMade : r.pairs;
  return unexplained == 0 ? 0 : kExitFailure;
}

}  // namespace

void addCheckCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Find intersecting quads of a tree's mesh and tell the skeleton's crossings from the mesher's. Exit code 0: "
      "no mesh-made pairs (an .obj: no pairs at all); 1: some; 2: bad input.");
  cmd->add_option("input", o->input,
                  "Preset name, model file (.json, Arbaro .xml: grown with --seed/--levels), skeleton or graph file (meshed; pairs classified), "
                  "or an .obj of quads (pairs counted, not classified)")
      ->required();
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--seed", o->seed, "Random seed for a preset or model file")->check(Seed())->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels to grow (default: the species' Levels)")->check(Whole(1, 8));
  cmd->add_option("--list", o->list, "Print the first N pairs: quads, stems, levels, contact, origin, a point")
      ->check(Whole(0, 1000000000));
  cmd->add_option("--json", o->json, "Write the counts and every pair to this JSON file");
  cmd->add_flag("--mesh-displaced", o->meshDisplaced,
                kMeshDisplacedHelp);
  cmd->callback([o, &action] { action = [o] { return runCheck(*o); }; });
}

}  // namespace arbor::cli
