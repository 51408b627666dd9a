#pragma once
// Everything a complete export holds (issue 18): the bark mesh at each level of detail, the fake-branch cards
// standing in for the levels each one leaves out, one alpha-masked card per leaf, and the textures. Exporters
// (glTF, OBJ) write this value; what grew the tree is not known here.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "growth/skeleton.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/mesh_options.hpp"
#include "mesh/quad_mesh.hpp"
#include "mesh/tree_mesh.hpp"
#include "tree/wind.hpp"

namespace arbor {

// Flat cards (leaves, fake branches) as quads: four corners each, counter-clockwise seen from the normal's side.
struct CardMesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec4> tangents;   // unit, along +u; w = -1 (v runs against the card's length)
  std::vector<glm::vec2> texcoords;  // glTF's convention: (0, 0) is the image's top-left texel
  std::vector<std::array<std::uint32_t, 4>> quads;

  bool empty() const { return quads.empty(); }
};

// How much of its atlas cell's width each leaf kind's blade fills (LeafKind order); the cards are widened by
// its inverse so the blade has the leaf's width. The same numbers as shaders/leaf.vert.
constexpr std::array<float, 4> kLeafBladeShare{0.82f, 0.30f, 0.95f, 0.70f};

// One flat card: corners counter-clockwise seen from the normal's side, texture coordinates in glTF's convention
// (as CardMesh's), the tangent along +u.
struct Card {
  std::array<glm::vec3, 4> corners;
  std::array<glm::vec2, 4> texcoords;
  glm::vec3 normal, tangent;
};

// One leaf's card, as the renderer draws it at full size: from the blade's base to its tip, textured with its
// kind's cell of the 2 x 2 leaf atlas (engine/image/leaf_atlas.hpp). Double-sided in use.
Card leafCard(const Leaf& leaf);

// leafCard of every leaf, in order.
CardMesh leafCards(const std::vector<Leaf>& leaves);

// The two crossed cards of a fake-branch segment (the renderer's eye-facing rectangle cannot face every eye of a
// static file): each as wide as the branch, reaching half a radius past both ends as the renderer's do, bark u
// across, v running on along the stem. None for a segment too short to have a direction.
std::optional<std::array<Card, 2>> segmentCards(const ImpostorSegment& segment);

// Whether segmentCards makes cards for the segment: it has a direction.
bool hasCards(const ImpostorSegment& segment);

// segmentCards of every segment, in order.
CardMesh branchCards(const std::vector<ImpostorSegment>& segments);

// One level of detail: the bark mesh of the levels it meshes and cards for the rest.
struct AssetLod {
  std::string name;        // "tupelo_lod0"
  int meshedLevels = 0;    // stem levels in the mesh (the deeper ones are cards)
  std::shared_ptr<const QuadMesh> bark;  // shared with the caller's mesh where it is the coarse one (no copy)
  std::vector<int> fakedStems;           // children that mesh left out (TreeMesh::fakedStems): cards too
  CardMesh branchCards;
  // With wind: per keyframe, each vertex's offset from its rest position (bark, then branch cards).
  std::vector<std::vector<glm::vec3>> barkPoses, branchCardPoses;
};

// PNG files' bytes; an empty string leaves that map out.
struct AssetTextures {
  std::string barkColor;   // sRGB base colour, tiles in u and v
  std::string barkNormal;  // tangent-space normal map, glTF's convention (green along -v, the image's up)
  std::string leafAtlas;   // RGBA, alpha-masked at 0.5
  bool empty() const { return barkColor.empty() && barkNormal.empty() && leafAtlas.empty(); }
};

struct TreeAsset {
  std::string name;
  std::vector<AssetLod> lods;  // lods[0] the most detailed; the others coarser, in order
  CardMesh leaves;             // shared by every level of detail
  std::vector<std::vector<glm::vec3>> leafPoses;  // with wind: per keyframe, each leaf corner's offset
  double windPeriod = 0.0;     // seconds the keyframes span, evenly, looping (0: no wind animation)
  AssetTextures textures;
};

struct TreeAssetOptions {
  MeshOptions mesh;        // for every level of detail; mesh.levels: the most detailed one's (0: all levels)
  int lods = 1;            // levels of detail: each next one fakes one more stem level (as long as the trunk stays)
  int subdivide = 0;       // Catmull-Clark levels applied to every bark mesh (OpenSubdiv)
  bool leaves = true;
  bool branchCards = true; // cards for the stem levels a level of detail does not mesh (and stubs, faked twigs)
  WindSettings wind;       // on: every level, card and leaf gets `windFrames` poses over one gust period
  int windFrames = 24;     // keyframes per period (the faster sways are coarser sampled; leaves do not flutter)
};

// The tree built at each level of detail (tree/build_tree), with its leaf and branch cards and, with wind, their
// poses (tree/wind: the cage posed, then subdivided); textures are the caller's (they live in the engine's
// assets). `finest`: the finest level's coarse mesh when the caller has built it already (with options.mesh); the
// asset shares it rather than copying it.
// `progress` hears each level of detail as it is built. Throws what buildTree and subdivide throw.
TreeAsset makeTreeAsset(const Skeleton& skeleton, const std::string& name, const TreeAssetOptions& options,
                        std::shared_ptr<const TreeMesh> finest = nullptr, const std::function<void(const std::string&)>& progress = {});

// A bark mesh alone: one level of detail, no cards, no textures (the exporters' simplest input).
TreeAsset barkOnlyAsset(std::shared_ptr<const QuadMesh> bark, const std::string& name);

}  // namespace arbor
