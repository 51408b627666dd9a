#include "tree_asset.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <utility>

#include <glm/geometric.hpp>

#include "subdivide.hpp"
#include "unit_vectors.hpp"
#include "tree/build_tree.hpp"

namespace arbor {

namespace {

using exporting::perpendicularTo;
using exporting::unitOr;

// Appends one card: corners[k] with texcoords[k], all facing `normal`, tangent along +u. glTF's bitangent
// (normal x tangent, times w) points up the image, against v; every card's v runs against its length, so w = -1.
void addCard(CardMesh& cards, const std::array<glm::vec3, 4>& corners, const std::array<glm::vec2, 4>& texcoords,
             const glm::vec3& normal, const glm::vec3& tangent) {
  const auto first = static_cast<std::uint32_t>(cards.positions.size());
  for (int k = 0; k < 4; ++k) {
    cards.positions.push_back(corners[static_cast<std::size_t>(k)]);
    cards.texcoords.push_back(texcoords[static_cast<std::size_t>(k)]);
    cards.normals.push_back(normal);
    cards.tangents.emplace_back(tangent, -1.0f);
  }
  cards.quads.push_back({first, first + 1, first + 2, first + 3});
}

// Room for `count` cards at once: grown a card at a time, a larch's 158,000 leaves were copied over and over.
void reserveCards(CardMesh& cards, std::size_t count) {
  cards.positions.reserve(4 * count);
  cards.normals.reserve(4 * count);
  cards.tangents.reserve(4 * count);
  cards.texcoords.reserve(4 * count);
  cards.quads.reserve(count);
}

void appendCards(CardMesh& to, const CardMesh& more) {
  const auto first = static_cast<std::uint32_t>(to.positions.size());
  to.positions.insert(to.positions.end(), more.positions.begin(), more.positions.end());
  to.normals.insert(to.normals.end(), more.normals.begin(), more.normals.end());
  to.tangents.insert(to.tangents.end(), more.tangents.begin(), more.tangents.end());
  to.texcoords.insert(to.texcoords.end(), more.texcoords.begin(), more.texcoords.end());
  for (const auto& q : more.quads) to.quads.push_back({q[0] + first, q[1] + first, q[2] + first, q[3] + first});
}

}  // namespace

Card leafCard(const Leaf& leaf) {
  const glm::vec3 along = unitOr(glm::vec3(leaf.direction), glm::vec3(0, 0, 1));
  glm::vec3 normal = unitOr(glm::vec3(leaf.normal), perpendicularTo(along));
  const glm::vec3 across = unitOr(glm::cross(normal, along), perpendicularTo(normal));
  normal = glm::normalize(glm::cross(along, across));  // exactly at right angles to the card
  const std::size_t kind = std::min<std::size_t>(leaf.kind, kLeafBladeShare.size() - 1);
  const float halfWidth = static_cast<float>(leaf.width) / kLeafBladeShare[kind];
  const float length = static_cast<float>(leaf.length);
  const glm::vec3 base(leaf.position);
  // The atlas cell of this kind; the blade's base at the cell's bottom edge, its tip at the top.
  const glm::vec2 cell = glm::vec2(static_cast<float>(kind % 2), static_cast<float>(kind / 2)) * 0.5f;
  // Counter-clockwise about the normal ((-across) x along = normal): +across, -across at the base, then the tip.
  return Card{{base + across * halfWidth, base - across * halfWidth, base + along * length - across * halfWidth,
               base + along * length + across * halfWidth},
              {cell + glm::vec2(0.5f, 0.5f), cell + glm::vec2(0.0f, 0.5f), cell, cell + glm::vec2(0.5f, 0.0f)},
              normal,
              across};
}

CardMesh leafCards(const std::vector<Leaf>& leaves) {
  CardMesh cards;
  reserveCards(cards, leaves.size());
  for (const Leaf& leaf : leaves) {
    const Card card = leafCard(leaf);
    addCard(cards, card.corners, card.texcoords, card.normal, card.tangent);
  }
  return cards;
}

bool hasCards(const ImpostorSegment& s) { return glm::distance(s.from, s.to) > 0.0; }

std::optional<std::array<Card, 2>> segmentCards(const ImpostorSegment& s) {
  if (!hasCards(s)) return std::nullopt;
  const glm::dvec3 a = s.from, b = s.to;
  const double length = glm::distance(a, b);
  const glm::dvec3 axis = (b - a) / length;
  // Two planes through the axis at right angles; the first holds the horizontal, so every stem's cards agree.
  const glm::vec3 side1 = unitOr(glm::vec3(glm::cross(axis, glm::dvec3(0, 0, 1))), perpendicularTo(glm::vec3(axis)));
  const glm::vec3 side2 = glm::normalize(glm::cross(glm::vec3(axis), side1));
  const glm::vec3 lo(a - axis * (0.5 * s.fromRadius)), hi(b + axis * (0.5 * s.toRadius));
  const auto r0 = static_cast<float>(s.fromRadius), r1 = static_cast<float>(s.toRadius);
  // glTF's v grows down the image; the bark's v grows along the stem, as on the mesh.
  const auto v0 = static_cast<float>(s.fromV), v1 = static_cast<float>(s.toV);
  auto card = [&](const glm::vec3& side) {
    return Card{{lo - side * r0, lo + side * r0, hi + side * r1, hi - side * r1},
                {glm::vec2(0.0f, v0), glm::vec2(1.0f, v0), glm::vec2(1.0f, v1), glm::vec2(0.0f, v1)},
                glm::normalize(glm::cross(side, glm::vec3(axis))),
                side};
  };
  return std::array<Card, 2>{card(side1), card(side2)};
}

CardMesh branchCards(const std::vector<ImpostorSegment>& segments) {
  CardMesh cards;
  reserveCards(cards, 2 * segments.size());
  for (const ImpostorSegment& s : segments) {
    if (const auto pair = segmentCards(s)) {
      for (const Card& card : *pair) addCard(cards, card.corners, card.texcoords, card.normal, card.tangent);
    }
  }
  return cards;
}

namespace {

// The keyframes' times: evenly over one period, the last one short of it (the loop returns to the first).
double keyframeTime(const TreeAssetOptions& options, int frame) { return options.wind.period() * frame / options.windFrames; }

// What the whole tree shares in the wind: its height (the trunk's bend) and its phase in the gusts.
struct WindTree {
  double height = 0.0, phase = 0.0;
};

// Each keyframe's offsets of the bark's vertices: the cage posed, then subdivided as the rest was.
std::vector<std::vector<glm::vec3>> barkPoses(const Skeleton& skeleton, const TreeMesh& cage, const QuadMesh& bark,
                                              const TreeAssetOptions& options, const WindTree& tree) {
  const std::vector<WindPoint> points = meshWindPoints(skeleton, cage);
  std::vector<std::vector<glm::vec3>> poses;
  for (int frame = 0; frame < options.windFrames; ++frame) {
    const double t = keyframeTime(options, frame);
    QuadMesh posed = cage.mesh;
    for (std::size_t v = 0; v < posed.vertexCount(); ++v) posed.positions[v] += windOffset(cage.mesh.positions[v], points[v], options.wind, tree.height, tree.phase, t);
    if (options.subdivide > 0) posed = subdivide(posed, options.subdivide, options.mesh.maxQuads);
    std::vector<glm::vec3> offsets(bark.vertexCount());
    for (std::size_t v = 0; v < offsets.size(); ++v) offsets[v] = posed.positions[v] - bark.positions[v];
    poses.push_back(std::move(offsets));
  }
  return poses;
}

// Branch cards move with the nodes at their ends (the layout of branchCards: two cards, eight corners, per segment).
std::vector<std::vector<glm::vec3>> branchCardPoses(const Skeleton& skeleton, const std::vector<ImpostorSegment>& segments,
                                                    const TreeAssetOptions& options, const WindTree& tree) {
  std::vector<std::array<WindPoint, 2>> ends;  // the carded segments' end nodes
  for (const ImpostorSegment& s : segments) {
    if (hasCards(s)) ends.push_back({nodeWindPoint(skeleton, s.fromNode), nodeWindPoint(skeleton, s.toNode)});
  }
  std::vector<std::vector<glm::vec3>> poses;
  for (int frame = 0; frame < options.windFrames; ++frame) {
    const double t = keyframeTime(options, frame);
    std::vector<glm::vec3> offsets;
    std::size_t carded = 0;
    for (const ImpostorSegment& s : segments) {
      if (!hasCards(s)) continue;
      const auto& [from, to] = ends[carded++];
      const glm::vec3 lo = windOffset(glm::vec3(s.from), from, options.wind, tree.height, tree.phase, t);
      const glm::vec3 hi = windOffset(glm::vec3(s.to), to, options.wind, tree.height, tree.phase, t);
      for (int card = 0; card < 2; ++card) offsets.insert(offsets.end(), {lo, lo, hi, hi});
    }
    poses.push_back(std::move(offsets));
  }
  return poses;
}

// Leaves move with the node they hang from (four corners per leaf, in leafCards' order).
std::vector<std::vector<glm::vec3>> leafPoses(const Skeleton& skeleton, const TreeAssetOptions& options, const WindTree& tree) {
  const std::vector<WindPoint> points = leafWindPoints(skeleton);
  std::vector<std::vector<glm::vec3>> poses;
  for (int frame = 0; frame < options.windFrames; ++frame) {
    const double t = keyframeTime(options, frame);
    std::vector<glm::vec3> offsets;
    offsets.reserve(4 * skeleton.leaves.size());
    for (std::size_t i = 0; i < skeleton.leaves.size(); ++i) {
      const glm::vec3 base = windOffset(glm::vec3(skeleton.leaves[i].position), points[i], options.wind, tree.height, tree.phase, t);
      offsets.insert(offsets.end(), {base, base, base, base});
    }
    poses.push_back(std::move(offsets));
  }
  return poses;
}

}  // namespace

namespace {

// What a level of detail draws beside its bark: the cards of the stems it leaves out (and of stubs).
struct LodCards {
  std::vector<ImpostorSegment> segments;
  CardMesh cards;
};

// The levels of detail's stem levels, finest first: each next one fakes one more level, the trunk always meshed.
std::vector<int> lodLevelsOf(const Skeleton& skeleton, const TreeAssetOptions& options) {
  const int levels = std::max(1, skeleton.levels);
  const int meshed = options.mesh.levels > 0 ? std::min(options.mesh.levels, levels) : levels;
  std::vector<int> result;
  for (int lod = 0; lod < std::max(1, options.lods) && meshed - lod >= 1; ++lod) result.push_back(meshed - lod);
  return result;
}

}  // namespace

TreeAsset makeTreeAsset(const Skeleton& skeleton, const std::string& name, const TreeAssetOptions& options, std::shared_ptr<const TreeMesh> finest,
                        const std::function<void(const std::string&)>& progress) {
  TreeAsset asset;
  asset.name = name;
  const std::vector<int> lodLevels = lodLevelsOf(skeleton, options);
  const WindTree windTree = options.wind.on() ? WindTree{windHeight(skeleton), windPhase(skeleton)} : WindTree{};
  // Cards need only the skeleton: they are made on another core while this one meshes (a tenth of a large export).
  std::future<std::pair<CardMesh, std::vector<LodCards>>> cardsMade = std::async(std::launch::async, [&] {
    std::vector<LodCards> lodCards;
    for (const int levels : lodLevels) {
      LodCards c{options.branchCards ? impostorSegments(skeleton, levels) : std::vector<ImpostorSegment>{}, {}};
      c.cards = branchCards(c.segments);
      lodCards.push_back(std::move(c));
    }
    return std::pair{options.leaves ? leafCards(skeleton.leaves) : CardMesh{}, std::move(lodCards)};
  });
  std::vector<std::shared_ptr<const TreeMesh>> cages;
  for (std::size_t lod = 0; lod < lodLevels.size(); ++lod) {
    if (progress) {
      progress("level of detail " + std::to_string(lod) + ": meshing stem levels 0-" + std::to_string(lodLevels[lod] - 1) +
               (options.subdivide > 0 ? ", " + std::to_string(options.subdivide) + " Catmull-Clark levels" : std::string()));
    }
    std::shared_ptr<const TreeMesh> coarse = finest;
    if (lod > 0 || finest == nullptr) {
      BuildOptions build;
      build.mesh = options.mesh;
      build.mesh.levels = lodLevels[lod];
      build.patches = false;
      coarse = std::make_shared<const TreeMesh>(buildTree(skeleton, build).mesh);
    }
    AssetLod level;
    level.name = name + "_lod" + std::to_string(lod);
    level.meshedLevels = lodLevels[lod];
    level.fakedStems = coarse->fakedStems;
    // Unsubdivided, the bark is the coarse mesh itself, shared (a copy was a sixth of a large export's time).
    level.bark = options.subdivide > 0 ? std::make_shared<const QuadMesh>(subdivide(coarse->mesh, options.subdivide, options.mesh.maxQuads))
                                       : std::shared_ptr<const QuadMesh>(coarse, &coarse->mesh);
    cages.push_back(std::move(coarse));
    asset.lods.push_back(std::move(level));
  }
  auto [leaves, lodCards] = cardsMade.get();
  asset.leaves = std::move(leaves);
  // Stubs are never meshed, so every level of detail has their cards too (wheat's grains).
  for (std::size_t lod = 0; lod < asset.lods.size(); ++lod) {
    AssetLod& level = asset.lods[lod];
    if (options.branchCards && !level.fakedStems.empty()) {  // known once meshed: their cards join the rest
      const std::vector<ImpostorSegment> faked = stemSegments(skeleton, level.fakedStems);
      lodCards[lod].segments.insert(lodCards[lod].segments.end(), faked.begin(), faked.end());
      appendCards(lodCards[lod].cards, branchCards(faked));
    }
    level.branchCards = std::move(lodCards[lod].cards);
    if (options.wind.on()) {
      if (progress) progress("level of detail " + std::to_string(lod) + ": " + std::to_string(options.windFrames) + " wind poses");
      level.barkPoses = barkPoses(skeleton, *cages[lod], *level.bark, options, windTree);
      level.branchCardPoses = branchCardPoses(skeleton, lodCards[lod].segments, options, windTree);
    }
  }
  if (options.wind.on()) {
    if (options.leaves) asset.leafPoses = leafPoses(skeleton, options, windTree);
    asset.windPeriod = options.wind.period();
  }
  return asset;
}

TreeAsset barkOnlyAsset(std::shared_ptr<const QuadMesh> bark, const std::string& name) {
  TreeAsset asset;
  asset.name = name;
  AssetLod level;
  level.name = name;
  level.bark = std::move(bark);
  asset.lods.push_back(std::move(level));
  return asset;
}

}  // namespace arbor
