#include "gltf_export.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "export_checks.hpp"

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

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return (length > 1e-12f && std::isfinite(length)) ? v / length : fallback;
}

// Any unit vector at right angles to the unit vector n, for a tangent that carries no information.
glm::vec3 perpendicularTo(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, axis));
}

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
    bufferViews.push_back({{"buffer", 0}, {"byteOffset", binary.size()}, {"byteLength", bytes}, {"target", target}});
    binary.append(reinterpret_cast<const char*>(values.data()), bytes);
    accessors.push_back({{"bufferView", bufferViews.size() - 1},
                         {"componentType", componentType},
                         {"count", count},
                         {"type", type}});
    return static_cast<int>(accessors.size() - 1);
  }
};

struct Asset {
  Json document;
  std::string binary;
};

Asset buildAsset(const QuadMesh& mesh, const std::string& name) {
  const char* context = "glTF export";
  exporting::requirePerVertex(mesh, mesh.normals.size(), "normals", context);
  exporting::requirePerVertex(mesh, mesh.tangents.size(), "tangents", context);
  exporting::requirePerVertex(mesh, mesh.uvw.size(), "uvw", context);
  exporting::requirePerVertex(mesh, mesh.radius.size(), "radii", context);
  exporting::requirePerVertex(mesh, mesh.level.size(), "levels", context);
  exporting::requireQuadIndicesInRange(mesh, context);
  if (mesh.quads.empty()) throw std::invalid_argument("glTF export: the mesh has no faces");

  const std::size_t n = mesh.vertexCount();
  const auto faceNormals = faceNormalSums(mesh);
  std::vector<float> positions, normals, tangents, texcoords, radius, level, flip;
  positions.reserve(3 * n);
  normals.reserve(3 * n);
  tangents.reserve(4 * n);
  texcoords.reserve(2 * n);
  radius.reserve(n);
  level.reserve(n);
  flip.reserve(n);
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (std::size_t i = 0; i < n; ++i) {
    // A NaN or infinity would make the file invalid, and always means a bug upstream.
    if (!isFinite(mesh.positions[i]) || !isFinite(mesh.uvw[i]) || !std::isfinite(mesh.radius[i])) {
      throw std::invalid_argument("glTF export: vertex " + std::to_string(i) + " has a non-finite position, uvw or radius");
    }
    const glm::vec3 p = yUp(mesh.positions[i]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    appendFloats(positions, p);
    const Frame f = orthonormalFrame(mesh.normals[i], mesh.tangents[i], faceNormals[i]);
    appendFloats(normals, yUp(f.normal));
    appendFloats(tangents, yUp(f.tangent));
    tangents.push_back(1.0f);
    texcoords.insert(texcoords.end(), {mesh.uvw[i].x, mesh.uvw[i].y});
    radius.push_back(mesh.radius[i]);
    level.push_back(static_cast<float>(mesh.level[i]));
    flip.push_back(mesh.uvw[i].z);
  }
  std::vector<std::uint32_t> indices;
  for (const auto& t : triangulate(mesh)) indices.insert(indices.end(), t.begin(), t.end());

  BufferAssembly buffer;
  Json attributes;
  attributes["POSITION"] = buffer.append(positions, n, "VEC3", kFloat, kArrayBuffer);
  // The validator compares these bounds with the data, so they are the floats' exact values, not rounded ones.
  buffer.accessors.back()["min"] = {static_cast<double>(lo.x), static_cast<double>(lo.y), static_cast<double>(lo.z)};
  buffer.accessors.back()["max"] = {static_cast<double>(hi.x), static_cast<double>(hi.y), static_cast<double>(hi.z)};
  attributes["NORMAL"] = buffer.append(normals, n, "VEC3", kFloat, kArrayBuffer);
  attributes["TANGENT"] = buffer.append(tangents, n, "VEC4", kFloat, kArrayBuffer);
  attributes["TEXCOORD_0"] = buffer.append(texcoords, n, "VEC2", kFloat, kArrayBuffer);
  attributes["_RADIUS"] = buffer.append(radius, n, "SCALAR", kFloat, kArrayBuffer);
  attributes["_LEVEL"] = buffer.append(level, n, "SCALAR", kFloat, kArrayBuffer);
  attributes["_FLIP"] = buffer.append(flip, n, "SCALAR", kFloat, kArrayBuffer);
  const int indexAccessor = buffer.append(indices, indices.size(), "SCALAR", kUnsignedInt, kElementArrayBuffer);

  Json doc;
  doc["asset"] = {{"version", "2.0"}, {"generator", "Arbor"}};
  doc["scene"] = 0;
  doc["scenes"] = Json::array({{{"name", name}, {"nodes", Json::array({0})}}});
  doc["nodes"] = Json::array({{{"name", name}, {"mesh", 0}}});
  Json primitive = {{"attributes", attributes}, {"indices", indexAccessor}, {"material", 0}, {"mode", kTriangles}};
  doc["meshes"] = Json::array({{{"name", name}, {"primitives", Json::array({primitive})}}});
  Json pbr = {{"baseColorFactor", {0.30, 0.22, 0.15, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}};
  doc["materials"] = Json::array({{{"name", "bark"}, {"pbrMetallicRoughness", pbr}}});
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

std::string writeGltf(const QuadMesh& mesh, const std::string& name) {
  Asset asset = buildAsset(mesh, name);
  asset.document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(asset.binary);
  return dumpJson(asset.document, 2) + "\n";
}

std::string writeGlb(const QuadMesh& mesh, const std::string& name) {
  const Asset asset = buildAsset(mesh, name);
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
