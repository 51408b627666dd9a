#include "gltf_export.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "export_checks.hpp"
#include "unit_vectors.hpp"

namespace arbor {

namespace {

using Json = nlohmann::ordered_json;

// The buffer is filled by copying memory, which is only right where memory order matches glTF's.
static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian");

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;
constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

// glTF is y up with -z ahead; Arbor is z up, so this turns the ground plane xy into xz without mirroring.
glm::vec3 yUp(const glm::vec3& v) { return {v.x, v.z, -v.y}; }

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

using exporting::perpendicularTo;
using exporting::unitOr;

// Area-weighted face normals: where a stored normal is degenerate, the surface itself says which way is out.
std::vector<glm::vec3> faceNormalSums(const QuadMesh& mesh) {
  std::vector<glm::vec3> sums(mesh.vertexCount(), glm::vec3(0));
  for (const auto& q : mesh.quads) {
    const auto& p = mesh.positions;
    const glm::vec3 n = glm::cross(p[q[2]] - p[q[0]], p[q[3]] - p[q[1]]);
    for (const std::uint32_t v : q) sums[v] += n;
  }
  return sums;
}

struct Frame {
  glm::vec3 normal, tangent;  // unit and orthogonal
};

Frame orthonormalFrame(const glm::vec3& normal, const glm::vec3& tangent, const glm::vec3& faceNormalSum) {
  Frame f;
  f.normal = unitOr(normal, unitOr(faceNormalSum, glm::vec3(0, 0, 1)));
  // Gram-Schmidt; a tangent (almost) along the normal has no usable direction left, so any one will do.
  const glm::vec3 inPlane = tangent - f.normal * glm::dot(f.normal, tangent);
  if (!(glm::length(inPlane) > 1e-3f * glm::length(tangent))) {
    f.tangent = perpendicularTo(f.normal);
    return f;
  }
  // A second pass removes what float cancellation left of the normal in the first.
  const glm::vec3 once = unitOr(inPlane, perpendicularTo(f.normal));
  f.tangent = unitOr(once - f.normal * glm::dot(f.normal, once), perpendicularTo(f.normal));
  return f;
}

void appendFloats(std::vector<float>& out, const glm::vec3& v) { out.insert(out.end(), {v.x, v.y, v.z}); }

// The binary buffer with one tightly packed view and one accessor per attribute.
struct BufferAssembly {
  std::string binary;
  Json bufferViews = Json::array();
  Json accessors = Json::array();

  template <class T>
  int append(const std::vector<T>& values, std::size_t count, const char* type, int componentType, int target) {
    static_assert(sizeof(T) == 4, "every component is 4 bytes, which keeps each view 4-byte aligned");
    const std::size_t bytes = values.size() * sizeof(T);
    bufferViews.push_back({{"buffer", 0}, {"byteOffset", binary.size()}, {"byteLength", bytes}});
    if (target != 0) bufferViews.back()["target"] = target;  // animation data is no vertex or index buffer
    binary.append(reinterpret_cast<const char*>(values.data()), bytes);
    accessors.push_back({{"bufferView", bufferViews.size() - 1},
                         {"componentType", componentType},
                         {"count", count},
                         {"type", type}});
    return static_cast<int>(accessors.size() - 1);
  }

  // Raw bytes (an image) in their own view; padded after so the next view stays 4-byte aligned.
  int appendBytes(const std::string& bytes) {
    bufferViews.push_back({{"buffer", 0}, {"byteOffset", binary.size()}, {"byteLength", bytes.size()}});
    binary += bytes;
    binary.append((4 - binary.size() % 4) % 4, '\0');
    return static_cast<int>(bufferViews.size() - 1);
  }
};

struct Asset {
  Json document;
  std::string binary;
};

constexpr int kLinear = 9729, kLinearMipmapLinear = 9987, kRepeat = 10497, kClampToEdge = 33071;

// Per vertex, the direction of increasing u and the handedness glTF's normal maps need (bitangent = normal x
// tangent * w points up the image, against v), from each face's texture-coordinate gradients. Where the flip
// coordinate mirrors u (its front and back lines) the gradients cancel, and the stored along-branch tangent
// gives the direction instead.
struct BarkFrame {
  Frame frame;
  float handedness = 1.0f;  // TANGENT's w
};

std::vector<BarkFrame> barkFrames(const QuadMesh& mesh, const std::vector<glm::vec3>& faceNormals) {
  std::vector<glm::dvec3> alongU(mesh.vertexCount(), glm::dvec3(0)), alongV(mesh.vertexCount(), glm::dvec3(0));
  for (const auto& q : mesh.quads) {
    for (const std::array<int, 3> t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
      const std::uint32_t a = q[static_cast<std::size_t>(t[0])], b = q[static_cast<std::size_t>(t[1])], c = q[static_cast<std::size_t>(t[2])];
      const glm::dvec3 e1 = glm::dvec3(mesh.positions[b]) - glm::dvec3(mesh.positions[a]);
      const glm::dvec3 e2 = glm::dvec3(mesh.positions[c]) - glm::dvec3(mesh.positions[a]);
      const glm::dvec2 d1 = glm::dvec2(mesh.uvw[b]) - glm::dvec2(mesh.uvw[a]), d2 = glm::dvec2(mesh.uvw[c]) - glm::dvec2(mesh.uvw[a]);
      const double r = d1.x * d2.y - d2.x * d1.y;
      if (r == 0.0) continue;
      // dP/du and dP/dv times the face's texture area, so larger faces weigh more.
      const double sign = r > 0.0 ? 1.0 : -1.0;
      const glm::dvec3 u = (e1 * d2.y - e2 * d1.y) * sign, v = (e2 * d1.x - e1 * d2.x) * sign;
      for (const std::uint32_t i : {a, b, c}) {
        alongU[i] += u;
        alongV[i] += v;
      }
    }
  }
  std::vector<BarkFrame> frames(mesh.vertexCount());
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    const glm::vec3 n = unitOr(mesh.normals[i], unitOr(faceNormals[i], glm::vec3(0, 0, 1)));
    const glm::vec3 v = unitOr(glm::vec3(alongV[i]), unitOr(mesh.tangents[i], perpendicularTo(n)));
    glm::vec3 u = glm::vec3(alongU[i]);
    // u cancelled out (a mirror line): at right angles to v, either way round is as right as the other.
    if (!(glm::length(u - n * glm::dot(n, u)) > 1e-3f * glm::length(u)) || glm::length(u) < 1e-20f) u = glm::cross(v, n);
    const Frame f = orthonormalFrame(n, u, faceNormals[i]);
    const float w = glm::dot(glm::cross(f.normal, f.tangent), v) < 0.0f ? 1.0f : -1.0f;
    frames[i] = {f, w};
  }
  return frames;
}

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

// The validator compares these bounds with the data, so they are the floats' exact values, not rounded ones.
void setBounds(Json& accessor, const Bounds& b) {
  accessor["min"] = {static_cast<double>(b.lo.x), static_cast<double>(b.lo.y), static_cast<double>(b.lo.z)};
  accessor["max"] = {static_cast<double>(b.hi.x), static_cast<double>(b.hi.y), static_cast<double>(b.hi.z)};
}

using Poses = std::vector<std::vector<glm::vec3>>;

// Morph targets: one POSITION accessor of offsets (glTF's axes) per pose; each target needs its bounds.
Json morphTargets(const Poses& poses, std::size_t vertices, BufferAssembly& buffer) {
  Json targets = Json::array();
  for (const auto& pose : poses) {
    if (pose.size() != vertices) throw std::invalid_argument("glTF export: a wind pose has another number of vertices than its primitive");
    std::vector<float> offsets;
    offsets.reserve(3 * vertices);
    Bounds bounds;
    for (const glm::vec3& d : pose) {
      if (!isFinite(d)) throw std::invalid_argument("glTF export: a wind pose is not finite");
      const glm::vec3 q = yUp(d);
      bounds.add(q);
      appendFloats(offsets, q);
    }
    if (vertices == 0) bounds = Bounds{glm::vec3(0), glm::vec3(0)};
    targets.push_back({{"POSITION", buffer.append(offsets, vertices, "VEC3", kFloat, kArrayBuffer)}});
    setBounds(buffer.accessors.back(), bounds);
  }
  return targets;
}

std::vector<std::uint32_t> flatten(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * triangles.size());
  for (const auto& t : triangles) indices.insert(indices.end(), t.begin(), t.end());
  return indices;
}

// The bark mesh's primitive attributes: POSITION, NORMAL, TANGENT, TEXCOORD_0 and Arbor's _RADIUS, _LEVEL, _FLIP.
Json barkPrimitive(const QuadMesh& mesh, BufferAssembly& buffer, int material, const Poses& poses) {
  const char* context = "glTF export";
  exporting::requirePerVertex(mesh, mesh.normals.size(), "normals", context);
  exporting::requirePerVertex(mesh, mesh.tangents.size(), "tangents", context);
  exporting::requirePerVertex(mesh, mesh.uvw.size(), "uvw", context);
  exporting::requirePerVertex(mesh, mesh.radius.size(), "radii", context);
  exporting::requirePerVertex(mesh, mesh.level.size(), "levels", context);
  exporting::requireQuadIndicesInRange(mesh, context);
  if (mesh.quads.empty()) throw std::invalid_argument("glTF export: the mesh has no faces");

  const std::size_t n = mesh.vertexCount();
  for (std::size_t i = 0; i < n; ++i) {
    // A NaN or infinity would make the file invalid, and always means a bug upstream.
    if (!isFinite(mesh.positions[i]) || !isFinite(mesh.uvw[i]) || !std::isfinite(mesh.radius[i])) {
      throw std::invalid_argument("glTF export: vertex " + std::to_string(i) + " has a non-finite position, uvw or radius");
    }
  }
  const auto faceNormals = faceNormalSums(mesh);
  const auto frames = barkFrames(mesh, faceNormals);
  std::vector<float> positions, normals, tangents, texcoords, radius, level, flip;
  positions.reserve(3 * n);
  normals.reserve(3 * n);
  tangents.reserve(4 * n);
  texcoords.reserve(2 * n);
  radius.reserve(n);
  level.reserve(n);
  flip.reserve(n);
  Bounds bounds;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 p = yUp(mesh.positions[i]);
    bounds.add(p);
    appendFloats(positions, p);
    appendFloats(normals, yUp(frames[i].frame.normal));
    appendFloats(tangents, yUp(frames[i].frame.tangent));
    tangents.push_back(frames[i].handedness);
    texcoords.insert(texcoords.end(), {mesh.uvw[i].x, mesh.uvw[i].y});
    radius.push_back(mesh.radius[i]);
    level.push_back(static_cast<float>(mesh.level[i]));
    flip.push_back(mesh.uvw[i].z);
  }
  Json attributes;
  attributes["POSITION"] = buffer.append(positions, n, "VEC3", kFloat, kArrayBuffer);
  setBounds(buffer.accessors.back(), bounds);
  attributes["NORMAL"] = buffer.append(normals, n, "VEC3", kFloat, kArrayBuffer);
  attributes["TANGENT"] = buffer.append(tangents, n, "VEC4", kFloat, kArrayBuffer);
  attributes["TEXCOORD_0"] = buffer.append(texcoords, n, "VEC2", kFloat, kArrayBuffer);
  attributes["_RADIUS"] = buffer.append(radius, n, "SCALAR", kFloat, kArrayBuffer);
  attributes["_LEVEL"] = buffer.append(level, n, "SCALAR", kFloat, kArrayBuffer);
  attributes["_FLIP"] = buffer.append(flip, n, "SCALAR", kFloat, kArrayBuffer);
  const auto indices = flatten(triangulate(mesh));
  const int indexAccessor = buffer.append(indices, indices.size(), "SCALAR", kUnsignedInt, kElementArrayBuffer);
  Json primitive = {{"attributes", attributes}, {"indices", indexAccessor}, {"material", material}, {"mode", kTriangles}};
  if (!poses.empty()) primitive["targets"] = morphTargets(poses, n, buffer);
  return primitive;
}

// Cards (leaves, fake branches): each quad as two triangles; the cards' frames are exact already.
// Tangents only where the material has a normal map (the validator notes unused ones).
Json cardPrimitive(const CardMesh& cards, BufferAssembly& buffer, int material, bool tangents, const Poses& poses) {
  const std::size_t n = cards.positions.size();
  if (cards.normals.size() != n || cards.tangents.size() != n || cards.texcoords.size() != n) {
    throw std::invalid_argument("glTF export: a card mesh needs one normal, tangent and texture coordinate per corner");
  }
  std::vector<float> positions, normals, frames, texcoords;
  Bounds bounds;
  for (std::size_t i = 0; i < n; ++i) {
    if (!isFinite(cards.positions[i])) throw std::invalid_argument("glTF export: card corner " + std::to_string(i) + " is not finite");
    const glm::vec3 p = yUp(cards.positions[i]);
    bounds.add(p);
    appendFloats(positions, p);
    appendFloats(normals, yUp(cards.normals[i]));
    appendFloats(frames, yUp(glm::vec3(cards.tangents[i])));
    frames.push_back(cards.tangents[i].w);
    texcoords.insert(texcoords.end(), {cards.texcoords[i].x, cards.texcoords[i].y});
  }
  std::vector<std::uint32_t> indices;
  indices.reserve(6 * cards.quads.size());
  for (const auto& q : cards.quads) {
    for (const std::uint32_t v : q) {
      if (v >= n) throw std::invalid_argument("glTF export: a card indexes past its corners");
    }
    indices.insert(indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  Json attributes;
  attributes["POSITION"] = buffer.append(positions, n, "VEC3", kFloat, kArrayBuffer);
  setBounds(buffer.accessors.back(), bounds);
  attributes["NORMAL"] = buffer.append(normals, n, "VEC3", kFloat, kArrayBuffer);
  if (tangents) attributes["TANGENT"] = buffer.append(frames, n, "VEC4", kFloat, kArrayBuffer);
  attributes["TEXCOORD_0"] = buffer.append(texcoords, n, "VEC2", kFloat, kArrayBuffer);
  const int indexAccessor = buffer.append(indices, indices.size(), "SCALAR", kUnsignedInt, kElementArrayBuffer);
  Json primitive = {{"attributes", attributes}, {"indices", indexAccessor}, {"material", material}, {"mode", kTriangles}};
  if (!poses.empty()) primitive["targets"] = morphTargets(poses, n, buffer);
  return primitive;
}

// Materials, textures, images and samplers, each added only when something uses it.
struct MaterialSet {
  const AssetTextures& files;
  BufferAssembly& buffer;
  Json materials = Json::array(), textures = Json::array(), images = Json::array(), samplers = Json::array();
  int bark = -1, branchCards = -1, leaves = -1;
  int repeatSampler = -1, clampSampler = -1;

  int texture(const std::string& png, const char* name, bool repeat) {
    int& sampler = repeat ? repeatSampler : clampSampler;
    if (sampler < 0) {
      const int wrap = repeat ? kRepeat : kClampToEdge;
      samplers.push_back({{"magFilter", kLinear}, {"minFilter", kLinearMipmapLinear}, {"wrapS", wrap}, {"wrapT", wrap}});
      sampler = static_cast<int>(samplers.size() - 1);
    }
    images.push_back({{"name", name}, {"bufferView", buffer.appendBytes(png)}, {"mimeType", "image/png"}});
    textures.push_back({{"sampler", sampler}, {"source", images.size() - 1}});
    return static_cast<int>(textures.size() - 1);
  }

  int barkMaterial(bool doubleSided) {
    int& slot = doubleSided ? branchCards : bark;
    if (slot >= 0) return slot;
    Json pbr = {{"baseColorFactor", {0.30, 0.22, 0.15, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}};
    Json material = {{"name", doubleSided ? "branch_cards" : "bark"}};
    if (!files.barkColor.empty()) {
      const int other = doubleSided ? bark : branchCards;  // both share the bark's textures
      pbr["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
      pbr["baseColorTexture"] = {{"index", other >= 0 ? materials[static_cast<std::size_t>(other)]["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>()
                                                      : texture(files.barkColor, "bark_color", true)}};
    }
    material["pbrMetallicRoughness"] = pbr;
    if (!files.barkNormal.empty()) {
      const int other = doubleSided ? bark : branchCards;
      material["normalTexture"] = {{"index", other >= 0 ? materials[static_cast<std::size_t>(other)]["normalTexture"]["index"].get<int>()
                                                        : texture(files.barkNormal, "bark_normal", true)}};
    }
    if (doubleSided) material["doubleSided"] = true;
    materials.push_back(std::move(material));
    return slot = static_cast<int>(materials.size() - 1);
  }

  int leafMaterial() {
    if (leaves >= 0) return leaves;
    Json pbr = {{"baseColorFactor", {0.25, 0.45, 0.15, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.7}};
    Json material = {{"name", "leaves"}};
    if (!files.leafAtlas.empty()) {
      pbr["baseColorFactor"] = {1.0, 1.0, 1.0, 1.0};
      pbr["baseColorTexture"] = {{"index", texture(files.leafAtlas, "leaf_atlas", false)}};
      material["alphaMode"] = "MASK";  // the atlas's cutouts: the renderer discards below 0.5 too
      material["alphaCutoff"] = 0.5;
    }
    material["pbrMetallicRoughness"] = pbr;
    material["doubleSided"] = true;
    materials.push_back(std::move(material));
    return leaves = static_cast<int>(materials.size() - 1);
  }
};

// What each level of detail is for, as MSFT_lod's screen coverage: the share of the screen's height below which
// the viewer moves to the next one (the last: below which the tree is not drawn).
constexpr double kScreenCoverage[] = {0.5, 0.2, 0.08, 0.03, 0.01};

Asset buildAsset(const TreeAsset& tree) {
  if (tree.lods.empty()) throw std::invalid_argument("glTF export: the asset has no level of detail");
  BufferAssembly buffer;
  MaterialSet materials{tree.textures, buffer};
  Json meshes = Json::array(), nodes = Json::array();
  std::optional<Json> leafPrimitive;
  const bool wind = tree.windPeriod > 0.0;
  const std::size_t poseCount = wind ? tree.lods.front().barkPoses.size() : 0;
  // Every primitive of a mesh needs the same targets: where a part has no poses, it gets none.
  auto posesOf = [&](const Poses& poses) -> const Poses& {
    if (wind && poses.size() != poseCount) throw std::invalid_argument("glTF export: every part needs the same number of wind poses");
    return poses;
  };
  if (!tree.leaves.empty()) leafPrimitive = cardPrimitive(tree.leaves, buffer, materials.leafMaterial(), false, posesOf(tree.leafPoses));
  for (const AssetLod& lod : tree.lods) {
    Json primitives = Json::array({barkPrimitive(*lod.bark, buffer, materials.barkMaterial(false), posesOf(lod.barkPoses))});
    if (!lod.branchCards.empty())
      primitives.push_back(cardPrimitive(lod.branchCards, buffer, materials.barkMaterial(true), !tree.textures.barkNormal.empty(), posesOf(lod.branchCardPoses)));
    if (leafPrimitive) primitives.push_back(*leafPrimitive);  // the same accessors in every level of detail
    Json mesh = {{"name", lod.name}, {"primitives", std::move(primitives)}};
    if (wind) mesh["weights"] = std::vector<double>(poseCount, 0.0);
    meshes.push_back(std::move(mesh));
    nodes.push_back({{"name", lod.name}, {"mesh", meshes.size() - 1}});
  }
  nodes[0]["name"] = tree.name;
  Json doc;
  doc["asset"] = {{"version", "2.0"}, {"generator", "Arbor"}};
  if (tree.lods.size() > 1) {
    // The coarser levels hang off the finest node only through the extension, so viewers without it show the finest.
    Json ids = Json::array(), coverage = Json::array();
    for (std::size_t i = 1; i < tree.lods.size(); ++i) ids.push_back(i);
    for (std::size_t i = 0; i < tree.lods.size(); ++i) coverage.push_back(kScreenCoverage[std::min<std::size_t>(i, std::size(kScreenCoverage) - 1)]);
    nodes[0]["extensions"] = {{"MSFT_lod", {{"ids", ids}}}};
    nodes[0]["extras"] = {{"MSFT_screencoverage", coverage}};
    doc["extensionsUsed"] = Json::array({"MSFT_lod"});
  }
  if (wind && poseCount > 0) {
    // One loop over the poses: at keyframe k pose k alone, blended linearly to the next, the last back to the first.
    std::vector<float> times, weights;
    for (std::size_t k = 0; k <= poseCount; ++k) {
      times.push_back(static_cast<float>(tree.windPeriod * static_cast<double>(k) / static_cast<double>(poseCount)));
      for (std::size_t j = 0; j < poseCount; ++j) weights.push_back(j == k % poseCount ? 1.0f : 0.0f);
    }
    const int input = buffer.append(times, times.size(), "SCALAR", kFloat, 0);
    buffer.accessors.back()["min"] = {static_cast<double>(times.front())};
    buffer.accessors.back()["max"] = {static_cast<double>(times.back())};
    const int output = buffer.append(weights, weights.size(), "SCALAR", kFloat, 0);
    Json channels = Json::array();
    for (std::size_t i = 0; i < tree.lods.size(); ++i) channels.push_back({{"sampler", 0}, {"target", {{"node", i}, {"path", "weights"}}}});
    doc["animations"] = Json::array({{{"name", "wind"},
                                      {"samplers", Json::array({{{"input", input}, {"output", output}, {"interpolation", "LINEAR"}}})},
                                      {"channels", std::move(channels)}}});
  }
  doc["scene"] = 0;
  doc["scenes"] = Json::array({{{"name", tree.name}, {"nodes", Json::array({0})}}});
  doc["nodes"] = std::move(nodes);
  doc["meshes"] = std::move(meshes);
  doc["materials"] = std::move(materials.materials);
  if (!materials.textures.empty()) {
    doc["textures"] = std::move(materials.textures);
    doc["images"] = std::move(materials.images);
    doc["samplers"] = std::move(materials.samplers);
  }
  doc["accessors"] = std::move(buffer.accessors);
  doc["bufferViews"] = std::move(buffer.bufferViews);
  doc["buffers"] = Json::array({{{"byteLength", buffer.binary.size()}}});
  return {std::move(doc), std::move(buffer.binary)};
}

std::string base64(const std::string& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    std::uint32_t group = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16;
    if (left > 1) group |= std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8;
    if (left > 2) group |= std::uint32_t{static_cast<unsigned char>(bytes[i + 2])};
    out += alphabet[(group >> 18) & 63];
    out += alphabet[(group >> 12) & 63];
    out += left > 1 ? alphabet[(group >> 6) & 63] : '=';
    out += left > 2 ? alphabet[group & 63] : '=';
  }
  return out;
}

// A user-supplied name that is not UTF-8 is patched rather than making the whole export fail.
std::string dumpJson(const Json& doc, int indent) { return doc.dump(indent, ' ', false, Json::error_handler_t::replace); }

void appendWord(std::string& out, std::uint32_t word) {
  char bytes[4];
  std::memcpy(bytes, &word, 4);
  out.append(bytes, 4);
}

std::uint32_t glbLength(std::size_t size) {
  if (size > std::numeric_limits<std::uint32_t>::max()) throw std::invalid_argument("GLB export: the asset exceeds 4 GiB");
  return static_cast<std::uint32_t>(size);
}

}  // namespace

// The caller's mesh outlives the call: the asset points at it without owning it.
std::string writeGltf(const QuadMesh& mesh, const std::string& name) { return writeGltf(barkOnlyAsset(std::shared_ptr<const QuadMesh>(std::shared_ptr<void>(), &mesh), name)); }

std::string writeGlb(const QuadMesh& mesh, const std::string& name) { return writeGlb(barkOnlyAsset(std::shared_ptr<const QuadMesh>(std::shared_ptr<void>(), &mesh), name)); }

std::string writeGltf(const TreeAsset& tree) {
  Asset asset = buildAsset(tree);
  asset.document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(asset.binary);
  return dumpJson(asset.document, 2) + "\n";
}

std::string writeGlb(const TreeAsset& tree) {
  const Asset asset = buildAsset(tree);
  std::string json = dumpJson(asset.document, -1);
  json.append((4 - json.size() % 4) % 4, ' ');  // chunks start on 4-byte boundaries; JSON pads with spaces
  std::string binary = asset.binary;
  binary.append((4 - binary.size() % 4) % 4, '\0');

  std::string glb;
  const std::size_t total = 12 + 8 + json.size() + 8 + binary.size();
  glb.reserve(total);
  appendWord(glb, kGlbMagic);
  appendWord(glb, 2);
  appendWord(glb, glbLength(total));
  appendWord(glb, glbLength(json.size()));
  appendWord(glb, kJsonChunk);
  glb += json;
  appendWord(glb, glbLength(binary.size()));
  appendWord(glb, kBinChunk);
  glb += binary;
  return glb;
}

}  // namespace arbor
