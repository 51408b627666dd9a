#include "crossing_twigs.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mesh_attributes.hpp"
#include "self_intersection.hpp"

namespace arbor {

namespace {

// A twig taken out can leave its parent a twig whose own quads cross: a second pass (a third found nothing on
// any tree at seeds 1-3).
constexpr int kPasses = 2;
// Stems from level 2 on can be twigs; a level-1 stem only when at most this share of its parent's radius thick
// (shave-grass's whorls, palm fronds): all trees at seeds 1-3 502 -> 319 pairs for 0.3 % of their quads (the fan
// palm file 5.4 %, shave-grass 4.9 %); at half the radius 254, but the willow preset lost 16 % of its quads. The
// parent's radius at its base, not where the twig attaches: a twig high on a tapering stem is as thick as the stem
// there and still a twig of the tree (all trees 276 -> 258 pairs, 0.04 % of their quads; the ABOP plants
// 231 -> 120, 0.3 %).
constexpr int kFromLevel = 2;
constexpr double kThinLevelOne = 0.25;
// A branch bearing only twigs goes with them (all trees at seeds 1-3: 562 -> 502 pairs, 0.24 % of the quads);
// bearing branches that bear twigs too (2) changed no tree but took 3 % of the ABOP plants' quads for 69 pairs.
constexpr int kMaxHeight = 1;

using Quad = std::array<std::uint32_t, 4>;

// Per stem, the stem its clones split from (itself when not a clone): a twig and its clones go together.
std::vector<int> familyRoots(const Skeleton& skeleton) {
  std::vector<int> root(skeleton.stems.size());
  for (std::size_t i = 0; i < root.size(); ++i) {
    int r = static_cast<int>(i);
    while (skeleton.stems[static_cast<std::size_t>(r)].cloneOf >= 0) r = skeleton.stems[static_cast<std::size_t>(r)].cloneOf;
    root[i] = r;
  }
  return root;
}

// Per stem, the twig this pass may take out that it belongs to (-1: none): a family (a stem with the clones it
// splits into) with quads, from level 2 on (or thin at level 1), whose meshed descendants lie at most kMaxHeight
// families below it (a branch bearing only twigs: they go with it); or, of a family too large for that, a clone
// as thin that ends it bearing nothing, alone (the desert bush file's forks a few centimetres long at its
// branches' ends, whose split boxes crossed a neighbouring fork's).
std::vector<int> twigsOf(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& root, int maxHeight = kMaxHeight) {
  const std::size_t n = skeleton.stems.size();
  std::vector<bool> meshed(n, false), bears(n, false);  // meshed: per family
  std::vector<int> height(n, 0), twig(n, -1);
  for (int s : tree.quadStem) {
    if (s >= 0 && static_cast<std::size_t>(s) < n) meshed[static_cast<std::size_t>(root[static_cast<std::size_t>(s)])] = true;
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      const SkeletonStem& st = skeleton.stems[i];
      if (st.cloneOf >= 0 || st.parentStem < 0 || !meshed[static_cast<std::size_t>(root[i])]) continue;
      int& up = height[static_cast<std::size_t>(root[static_cast<std::size_t>(st.parentStem)])];
      if (up < height[static_cast<std::size_t>(root[i])] + 1) {
        up = height[static_cast<std::size_t>(root[i])] + 1;
        changed = true;
      }
    }
  }
  // Whether a stem, or a clone splitting from it, bears a meshed child.
  for (std::size_t i = 0; i < n; ++i) {
    const SkeletonStem& st = skeleton.stems[i];
    if (st.cloneOf >= 0 || st.parentStem < 0 || !meshed[static_cast<std::size_t>(root[i])]) continue;
    for (int x = st.parentStem; x >= 0 && !bears[static_cast<std::size_t>(x)]; x = skeleton.stems[static_cast<std::size_t>(x)].cloneOf) {
      bears[static_cast<std::size_t>(x)] = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const SkeletonStem& r = skeleton.stems[static_cast<std::size_t>(root[i])];
    const auto ri = static_cast<std::size_t>(root[i]);
    if (r.parentStem < 0 || !meshed[ri]) continue;  // a trunk is never a twig
    const double thinAt = kThinLevelOne * skeleton.stems[static_cast<std::size_t>(r.parentStem)].startRadius;
    if (height[ri] <= maxHeight && (r.level >= kFromLevel || (r.level == kFromLevel - 1 && r.startRadius <= thinAt))) {
      twig[i] = root[i];
      continue;
    }
    // The outermost clone on the way back to the family's root that bears nothing, with what splits from it.
    for (int x = static_cast<int>(i); x >= 0;) {
      const SkeletonStem& c = skeleton.stems[static_cast<std::size_t>(x)];
      if (c.cloneOf < 0 || bears[static_cast<std::size_t>(x)] || (r.level < kFromLevel && c.startRadius > thinAt)) break;
      twig[i] = x;
      x = c.cloneOf;
    }
  }
  return twig;
}

// The twig a mesh-made pair takes out: of two, the one whose quad strays farther from its skeleton.
int culprit(const QuadPairHit& h, const std::vector<int>& twig, const Skeleton& skeleton) {
  const int a = h.stemA >= 0 ? twig[static_cast<std::size_t>(h.stemA)] : -1;
  const int b = h.stemB >= 0 ? twig[static_cast<std::size_t>(h.stemB)] : -1;
  // A neck through its own parent: the child's.
  if (h.throughParent) return childIsA(h, skeleton) ? a : b;
  if (a >= 0 && (b < 0 || h.reachA >= h.reachB)) return a;
  return b;
}

// The twigs, sorted and each once, that the pairs `taken(h)` picks take out.
template <class Taken>
std::vector<int> culpritsOf(const std::vector<QuadPairHit>& hits, const std::vector<int>& twig, const Skeleton& skeleton, Taken&& taken) {
  std::vector<int> culprits;
  for (const QuadPairHit& h : hits) {
    if (const int c = taken(h) ? culprit(h, twig, skeleton) : -1; c >= 0) culprits.push_back(c);
  }
  std::sort(culprits.begin(), culprits.end());
  culprits.erase(std::unique(culprits.begin(), culprits.end()), culprits.end());
  return culprits;
}

// The face that closes a twig's port once its quads are gone: its quads' four edges that no other of its quads
// shares, in order (the parent's face there, as the twig's first band ran on from it). None when the twig meets
// the rest of the mesh otherwise, or one of its inner vertices is also another stem's.
std::optional<Quad> portFace(const QuadMesh& mesh, const std::vector<std::uint32_t>& quads, const std::vector<std::uint32_t>& uses) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t f : quads) {
    for (std::size_t k = 0; k < 4; ++k) edges.emplace_back(mesh.quads[f][k], mesh.quads[f][(k + 1) % 4]);
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> open;
  for (const auto& [a, b] : edges) {
    if (!std::binary_search(edges.begin(), edges.end(), std::pair{b, a})) open.emplace_back(a, b);
  }
  if (open.size() != 4) return std::nullopt;
  Quad face{open[0].first, open[0].second, 0, 0};
  for (std::size_t k = 2; k < 4; ++k) {
    const auto next = std::find_if(open.begin(), open.end(), [&](const auto& e) { return e.first == face[k - 1]; });
    if (next == open.end()) return std::nullopt;
    face[k] = next->second;
  }
  const auto last = std::find_if(open.begin(), open.end(), [&](const auto& e) { return e.first == face[3]; });
  if (last == open.end() || last->second != face[0]) return std::nullopt;
  // Every other vertex of the twig must be the twig's alone, or taking its quads out would open another hole.
  std::vector<std::uint32_t> own;
  for (std::uint32_t f : quads) own.insert(own.end(), mesh.quads[f].begin(), mesh.quads[f].end());
  std::sort(own.begin(), own.end());
  for (auto v = own.begin(); v != own.end();) {
    const auto end = std::upper_bound(v, own.end(), *v);
    const bool onPort = std::find(face.begin(), face.end(), *v) != face.end();
    if (!onPort && uses[*v] != static_cast<std::uint32_t>(end - v)) return std::nullopt;
    v = end;
  }
  return face;
}

// Moves each kept vertex's value to its new index (never above its old one), in place.
template <class T>
void keepVertices(std::vector<T>& values, const std::vector<std::uint32_t>& newIndex, std::uint32_t kept) {
  if (values.size() != newIndex.size()) return;
  for (std::size_t v = 0; v < values.size(); ++v) {
    if (newIndex[v] != UINT32_MAX) values[newIndex[v]] = values[v];
  }
  values.resize(kept);
}

struct TakenOut {
  std::vector<int> twigs;    // the families' roots
  std::vector<int> members;  // every stem of theirs that had quads, sorted
  std::vector<std::uint32_t> ports;  // the faces that closed their ports, in the mesh after, sorted
};

// What taking the listed twigs (sorted) out would do: per twig, the quads that go with it (its own, its clones' and
// what grows from them), and the face that closes its port (none where one cannot: it stays).
struct TakeOutPlan {
  std::vector<std::vector<std::uint32_t>> quadsOf;
  std::vector<std::optional<Quad>> ports;
  std::vector<int> ownerOf;  // per quad, the twig (index into the list) it goes with, or -1
};

TakeOutPlan planTakeOut(const TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& twigs) {
  const QuadMesh& mesh = tree.mesh;
  std::vector<std::uint32_t> uses(mesh.vertexCount(), 0);
  for (const Quad& q : mesh.quads) {
    for (std::uint32_t v : q) ++uses[v];
  }
  // Per stem, the outermost of the twigs taken out that it belongs to (itself, a clone it splits from, its family,
  // or one it grows from).
  std::vector<int> takenWith(skeleton.stems.size(), -2);
  auto ownerOf = [&](int s) {
    int found = -1;
    for (int x = s; x >= 0; x = grownFrom(skeleton, x)) {
      const auto it = std::lower_bound(twigs.begin(), twigs.end(), x);
      if (it != twigs.end() && *it == x) found = static_cast<int>(it - twigs.begin());
    }
    return found;
  };
  TakeOutPlan plan;
  plan.quadsOf.resize(twigs.size());
  plan.ownerOf.assign(tree.quadStem.size(), -1);
  for (std::uint32_t f = 0; f < tree.quadStem.size(); ++f) {
    const int s = tree.quadStem[f];
    if (s < 0) continue;
    int& owner = takenWith[static_cast<std::size_t>(s)];
    if (owner == -2) owner = ownerOf(s);
    if (owner < 0) continue;
    plan.ownerOf[f] = owner;
    plan.quadsOf[static_cast<std::size_t>(owner)].push_back(f);
  }
  plan.ports.resize(twigs.size());
  for (std::size_t t = 0; t < twigs.size(); ++t) plan.ports[t] = portFace(mesh, plan.quadsOf[t], uses);
  return plan;
}

// Takes the listed twigs' quads out, closes each port, drops the vertices no quad uses any more; returns the
// twigs taken out (those with a port to close; with `allOrNothing`, none unless every twig with quads has one).
TakenOut takeOut(TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& twigs,
                 bool allOrNothing = false) {
  QuadMesh& mesh = tree.mesh;
  const TakeOutPlan plan = planTakeOut(tree, skeleton, twigs);
  TakenOut out;
  for (std::size_t t = 0; t < twigs.size(); ++t) {
    if (plan.ports[t]) out.twigs.push_back(twigs[t]);
    if (allOrNothing && !plan.ports[t] && !plan.quadsOf[t].empty()) return TakenOut{};
  }
  if (out.twigs.empty()) return out;
  // The port's face takes the place of the twig's first quad; the twig's other quads go.
  std::vector<Quad> quads;
  std::vector<int> quadStem;
  quads.reserve(mesh.quads.size());
  quadStem.reserve(mesh.quads.size());
  std::vector<int>& members = out.members;
  for (std::uint32_t f = 0; f < mesh.quads.size(); ++f) {
    const int t = plan.ownerOf[f];
    if (t < 0 || !plan.ports[static_cast<std::size_t>(t)]) {
      quads.push_back(mesh.quads[f]);
      quadStem.push_back(tree.quadStem[f]);
      continue;
    }
    members.push_back(tree.quadStem[f]);
    const auto twig = static_cast<std::size_t>(t);
    if (plan.quadsOf[twig].front() == f) {
      out.ports.push_back(static_cast<std::uint32_t>(quads.size()));
      quads.push_back(*plan.ports[twig]);
      quadStem.push_back(grownFrom(skeleton, twigs[twig]));
    }
  }
  std::sort(members.begin(), members.end());
  members.erase(std::unique(members.begin(), members.end()), members.end());
  std::vector<std::uint32_t> newIndex(mesh.vertexCount(), UINT32_MAX);
  for (const Quad& q : quads) {
    for (std::uint32_t v : q) newIndex[v] = 0;
  }
  for (std::uint32_t v : mesh.openBoundary) newIndex[v] = 0;
  std::uint32_t kept = 0;
  for (std::uint32_t& n : newIndex) {
    if (n == 0) n = kept++;
  }
  for (Quad& q : quads) {
    for (std::uint32_t& v : q) v = newIndex[v];
  }
  for (std::uint32_t& v : mesh.openBoundary) v = newIndex[v];
  keepVertices(mesh.positions, newIndex, kept);
  keepVertices(mesh.tangents, newIndex, kept);
  keepVertices(mesh.uvw, newIndex, kept);
  keepVertices(mesh.radius, newIndex, kept);
  keepVertices(mesh.level, newIndex, kept);
  mesh.quads = std::move(quads);
  tree.quadStem = std::move(quadStem);
  auto gone = [&](int stem) { return std::binary_search(members.begin(), members.end(), stem); };
  std::erase_if(tree.rings, [&](const MeshRing& r) { return gone(r.stem); });
  for (MeshRing& r : tree.rings) {
    for (std::uint32_t& v : r.vertices) v = newIndex[v];
  }
  for (MeshJoint& j : tree.joints) std::erase_if(j.childStems, gone);
  tree.fakedStems.insert(tree.fakedStems.end(), members.begin(), members.end());
  return out;
}

// Last, the twigs whose neck runs through their own parent (pairs left in `hits` with throughParent), each port's
// face tried in place first: a twig whose closed port would cross the mesh where the skeleton does not stays (a
// random graph's trunk face crossed three of the trunk's own quads), since the skeleton made the pair it was taken for.
std::size_t takeOutNecksThroughParents(TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& root, const std::vector<QuadPairHit>& hits) {
  if (std::none_of(hits.begin(), hits.end(), [](const QuadPairHit& h) { return h.throughParent; })) return 0;
  const std::vector<int> culprits =
      culpritsOf(hits, twigsOf(tree, skeleton, root), skeleton, [](const QuadPairHit& h) { return h.throughParent; });
  if (culprits.empty()) return 0;
  // The faces that would close the ports, added for the search and taken off again; pairs with quads that go
  // with a twig do not count.
  const TakeOutPlan plan = planTakeOut(tree, skeleton, culprits);
  const std::size_t n = tree.mesh.quads.size();
  std::vector<std::uint32_t> faces;
  std::vector<std::size_t> faceTwig;
  for (std::size_t t = 0; t < culprits.size(); ++t) {
    if (!plan.ports[t]) continue;
    faces.push_back(static_cast<std::uint32_t>(tree.mesh.quads.size()));
    faceTwig.push_back(t);
    tree.mesh.quads.push_back(*plan.ports[t]);
    tree.quadStem.push_back(grownFrom(skeleton, culprits[t]));
  }
  const std::vector<QuadPairHit> atPorts = pairsToMendWith(tree, skeleton, faces);
  tree.mesh.quads.resize(n);
  tree.quadStem.resize(n);
  std::vector<bool> crosses(culprits.size(), false);
  auto goes = [&](std::uint32_t f) { return f < n && plan.ownerOf[f] >= 0 && plan.ports[static_cast<std::size_t>(plan.ownerOf[f])]; };
  for (const QuadPairHit& h : atPorts) {
    if (h.origin != PairOrigin::Mesh) continue;
    for (const auto& [face, other] : {std::pair{h.a, h.b}, std::pair{h.b, h.a}}) {
      if (face >= n && !goes(other)) crosses[faceTwig[face - n]] = true;
    }
  }
  std::vector<int> kept;
  for (std::size_t t = 0; t < culprits.size(); ++t) {
    if (plan.ports[t] && !crosses[t]) kept.push_back(culprits[t]);
  }
  return kept.empty() ? 0 : takeOut(tree, skeleton, kept).twigs.size();
}

}  // namespace

bool takeOutTwigs(TreeMesh& tree, const Skeleton& skeleton, const std::vector<int>& stems) {
  const std::vector<int> root = familyRoots(skeleton);
  std::vector<int> twigs;
  for (int s : stems) {
    if (s < 0 || static_cast<std::size_t>(s) >= skeleton.stems.size() || root[static_cast<std::size_t>(s)] != s) return false;
    twigs.push_back(s);
  }
  std::sort(twigs.begin(), twigs.end());
  twigs.erase(std::unique(twigs.begin(), twigs.end()), twigs.end());
  if (twigs.empty()) return true;
  return !takeOut(tree, skeleton, twigs, true).twigs.empty();
}

std::size_t fakeCrossingTwigs(TreeMesh& tree, const Skeleton& skeleton, CrossingsLeft* left, PairsToMendSearch* begun) {
  const bool normals = tree.mesh.normals.size() == tree.mesh.positions.size();  // the builder's mesh has none yet
  const std::vector<int> root = familyRoots(skeleton);
  // One search, for every stem that is a twig or becomes one once its twigs are taken out (or every stem, to say
  // what is left): the second pass only looks again at the pairs found.
  auto flagged = [&] {
    std::vector<bool> deep(skeleton.stems.size(), true);
    if (left) return deep;  // every stem: no twigs to work out
    const std::vector<int> deepTwigs = twigsOf(tree, skeleton, root, kMaxHeight + 1);
    for (std::size_t i = 0; i < deep.size(); ++i) deep[i] = deepTwigs[i] >= 0;
    return deep;
  };
  std::vector<QuadPairHit> hits = left && begun ? begun->finish(tree, skeleton) : pairsToMendOf(tree, skeleton, flagged());
  auto meshMade = [](const QuadPairHit& h) { return h.origin == PairOrigin::Mesh; };
  std::size_t taken = 0;
  for (int pass = 0; pass < kPasses && std::any_of(hits.begin(), hits.end(), meshMade); ++pass) {
    const std::vector<int> culprits = culpritsOf(hits, twigsOf(tree, skeleton, root), skeleton, meshMade);
    if (culprits.empty()) break;
    const TakenOut out = takeOut(tree, skeleton, culprits);
    if (out.twigs.empty()) break;
    taken += out.twigs.size();
    auto gone = [&](int stem) { return std::binary_search(out.members.begin(), out.members.end(), stem); };
    std::erase_if(hits, [&](const QuadPairHit& h) { return gone(h.stemA) || gone(h.stemB); });
    // A face that closed a port is new: the neck of a twig beside the one taken out may cross it (shave-grass's
    // whorls: all trees at seeds 1-3 290 -> 276 pairs).
    if (pass + 1 < kPasses) {
      const std::vector<QuadPairHit> fresh = pairsToMendWith(tree, skeleton, out.ports);
      hits.insert(hits.end(), fresh.begin(), fresh.end());
    }
  }
  if (left) {
    *left = CrossingsLeft{};
    for (const QuadPairHit& h : hits) {
      if (!meshMade(h)) continue;
      ++left->pairs;
      left->necks.push_back(h.reachA >= h.reachB ? h.stemA : h.stemB);
    }
    std::sort(left->necks.begin(), left->necks.end());
    left->necks.erase(std::unique(left->necks.begin(), left->necks.end()), left->necks.end());
    std::erase_if(left->necks, [](int s) { return s < 0; });
  }
  taken += takeOutNecksThroughParents(tree, skeleton, root, hits);
  if (taken > 0 && normals) computeNormals(tree.mesh);
  return taken;
}

}  // namespace arbor
