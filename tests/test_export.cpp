// Exports: OBJ round trips bit for bit, glTF/GLB pass the Khronos validator and are y up, and OpenSubdiv
// subdivision keeps the mesh closed, oriented and on the limit surface it should be on.
// The meshes are built here (a cube and a capped tube) so these tests do not depend on the mesh builder.
#include <catch2/catch.hpp>
#include <array>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <sys/stat.h>

#include <glm/geometric.hpp>

#include "common/atomic_file.hpp"
#include "export/gltf_export.hpp"
#include "export/obj_export.hpp"
#include "export/subdivide.hpp"
#include "export/tree_asset.hpp"
#include "growth/weber_penn/weber_penn.hpp"
#include "image/png_io.hpp"
#include "tree/build_tree.hpp"
#include "test_support.hpp"

using namespace arbor;
using Catch::Matchers::Contains;

namespace {

void addVertex(QuadMesh& m, glm::vec3 p, glm::vec3 normal, glm::vec3 tangent, glm::vec3 uvw, float radius, std::uint8_t level) {
  m.positions.push_back(p);
  m.normals.push_back(glm::normalize(normal));
  m.tangents.push_back(glm::normalize(tangent));
  m.uvw.push_back(uvw);
  m.radius.push_back(radius);
  m.level.push_back(level);
}

// The cube [-1, 1] x [-1, 1] x [0, 2]: vertex i has x from bit 0, y from bit 1, z from bit 2.
QuadMesh cube() {
  QuadMesh m;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 2.0f : 0.0f);
    const glm::vec3 uvw((p.x + 1) / 2, p.z / 2, p.y > 0 ? 1.0f : 0.0f);
    addVertex(m, p, p - glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), uvw, 1.0f, 0);
  }
  m.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

constexpr float kTubeRadius = 0.5f;
constexpr float kRingSpacing = 1.0f;

std::uint32_t tubeVertex(int ring, int j) { return static_cast<std::uint32_t>(ring * 4 + (j % 4)); }

// `rings` square rings of 4 vertices along z (vertices on the x and y axes), side quads between them, and
// a cap quad at each end unless `openBase`, in which case ring 0 is the open boundary.
QuadMesh tube(int rings, bool openBase = false) {
  QuadMesh m;
  for (int k = 0; k < rings; ++k) {
    const float z = static_cast<float>(k) * kRingSpacing;
    for (int j = 0; j < 4; ++j) {
      const double angle = j * std::numbers::pi / 2;
      const glm::vec3 outward(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)), 0.0f);
      const float u = j == 0 ? 0.0f : j == 2 ? 1.0f : 0.5f;  // mirrored around the ring
      const glm::vec3 uvw(u, z, j == 3 ? 1.0f : 0.0f);
      addVertex(m, kTubeRadius * outward + glm::vec3(0, 0, z), outward, glm::vec3(0, 0, 1), uvw, kTubeRadius,
                static_cast<std::uint8_t>(2 * k < rings ? 0 : 1));
    }
  }
  for (int k = 0; k + 1 < rings; ++k) {
    for (int j = 0; j < 4; ++j) {
      m.quads.push_back({tubeVertex(k, j), tubeVertex(k, j + 1), tubeVertex(k + 1, j + 1), tubeVertex(k + 1, j)});
    }
  }
  if (openBase) {
    m.openBoundary = {tubeVertex(0, 0), tubeVertex(0, 1), tubeVertex(0, 2), tubeVertex(0, 3)};
  } else {
    m.quads.push_back({tubeVertex(0, 0), tubeVertex(0, 3), tubeVertex(0, 2), tubeVertex(0, 1)});
  }
  const int top = rings - 1;
  m.quads.push_back({tubeVertex(top, 0), tubeVertex(top, 1), tubeVertex(top, 2), tubeVertex(top, 3)});
  return m;
}

using DirectedEdges = std::map<std::pair<std::uint32_t, std::uint32_t>, int>;

DirectedEdges directedEdges(const QuadMesh& m) {
  DirectedEdges edges;
  for (const auto& q : m.quads) {
    for (int i = 0; i < 4; ++i) ++edges[{q[i], q[(i + 1) % 4]}];
  }
  return edges;
}

// Closed and consistently oriented: each directed edge once, and its reverse once (from the neighbour).
void requireClosedAndOriented(const QuadMesh& m) {
  const DirectedEdges edges = directedEdges(m);
  int problems = 0;
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) ++problems;
  }
  CHECK(problems == 0);
  CHECK(edges.size() == 4 * m.quads.size());
}

// The stored normal at every corner of every quad agrees with the quad's own outward normal.
int normalsAgainstFaces(const QuadMesh& m) {
  int wrong = 0;
  for (const auto& q : m.quads) {
    const auto& p = m.positions;
    const glm::vec3 face = glm::cross(p[q[2]] - p[q[0]], p[q[3]] - p[q[1]]);
    for (const std::uint32_t v : q) wrong += glm::dot(face, m.normals[v]) <= 0 ? 1 : 0;
  }
  return wrong;
}

using Run = test::CommandResult;

Run validate(const std::string& file) {
  return test::runCommand("node '" + std::string(ARBOR_SOURCE_DIR) + "/tools/validate-gltf.mjs' '" + file + "' 2>&1");
}

std::uint32_t word(const std::string& bytes, std::size_t at) {
  std::uint32_t w = 0;
  REQUIRE(at + 4 <= bytes.size());
  std::memcpy(&w, bytes.data() + at, 4);
  return w;
}

struct Glb {
  nlohmann::json json;
  std::string binary;  // the BIN chunk, padding included
};

// Splits a GLB after checking every length in it against the others.
Glb splitGlb(const std::string& glb) {
  REQUIRE(glb.size() >= 28);
  CHECK(word(glb, 0) == 0x46546C67);
  CHECK(word(glb, 4) == 2);
  CHECK(word(glb, 8) == glb.size());
  const std::uint32_t jsonLength = word(glb, 12);
  CHECK(word(glb, 16) == 0x4E4F534A);
  CHECK(jsonLength % 4 == 0);
  const std::size_t binAt = 20 + std::size_t{jsonLength};
  const std::uint32_t binLength = word(glb, binAt);
  CHECK(word(glb, binAt + 4) == 0x004E4942);
  CHECK(binLength % 4 == 0);
  REQUIRE(binAt + 8 + binLength == glb.size());
  Glb out{nlohmann::json::parse(glb.substr(20, jsonLength)), glb.substr(binAt + 8, binLength)};
  const std::size_t declared = out.json["buffers"][0]["byteLength"];
  CHECK(declared <= binLength);
  CHECK(binLength - declared < 4);
  return out;
}

std::vector<float> accessorFloats(const nlohmann::json& doc, const std::string& binary, int accessor, int components) {
  const auto& a = doc["accessors"][accessor];
  const auto& view = doc["bufferViews"][a["bufferView"].get<int>()];
  const std::size_t offset = view.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
  const std::size_t count = a["count"].get<std::size_t>() * static_cast<std::size_t>(components);
  REQUIRE(a["componentType"] == 5126);
  REQUIRE(offset + count * 4 <= binary.size());
  std::vector<float> values(count);
  std::memcpy(values.data(), binary.data() + offset, count * 4);
  return values;
}

std::string decodeBase64(const std::string& text) {
  std::string out;
  std::uint32_t group = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* at = std::strchr(alphabet, c);
    REQUIRE((at && c != '\0'));
    group = (group << 6) | static_cast<std::uint32_t>(at - alphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((group >> bits) & 0xFF);
    }
  }
  return out;
}

std::string writeTemp(const std::string& name, const std::string& content) {
  const std::string path = test::tempPath(name);
  writeFileAtomically(path, content);
  return path;
}

}  // namespace

// ---------------------------------------------------------------- files

TEST_CASE("a file written atomically holds exactly what was streamed, with no blocks reserved past its end", "[export][file]") {
  // Single characters, short runs and blocks larger than the sink's buffer, past several reservation steps.
  std::string expected;
  std::uint32_t state = 12345;
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  const std::string path = test::tempPath("streamed.bin");
  writeFileAtomically(path, [&](std::ostream& out) {
    while (expected.size() < (std::size_t{11} << 20)) {
      const std::size_t n = next() % 3 == 0 ? 1 : next() % 2 == 0 ? next() % 300 : (std::size_t{1} << 20) + next() % 1000;
      std::string piece(n, '\0');
      for (char& c : piece) c = static_cast<char>(next() >> 24);
      if (n == 1) out.put(piece[0]);
      else out.write(piece.data(), static_cast<std::streamsize>(n));
      expected += piece;
    }
  });
  CHECK(readFile(path) == expected);
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  CHECK(static_cast<std::size_t>(info.st_size) == expected.size());
  // Reservations come in steps of 4 MiB or more (the last here ends 1 MiB past the data): one left over shows.
  CHECK(static_cast<std::size_t>(info.st_blocks) * 512 < expected.size() + (std::size_t{64} << 10));
}

TEST_CASE("a staged copy, committed, holds the source's bytes over the old file, leaves the same bytes alone, and a missing source changes nothing", "[export][file]") {
  std::string bytes(std::size_t{3} << 20, '\0');  // past the sink's buffer, with every byte value
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
  const std::string from = writeTemp("copy-source.bin", bytes);
  const std::string to = writeTemp("copy-target.bin", "the old content, longer than nothing");
  stageCopy(from, to).commit();
  CHECK(readFile(to) == bytes);
  // The same bytes again: the file is left as it is (the same inode, not renamed over).
  struct stat before {}, after {};
  REQUIRE(::stat(to.c_str(), &before) == 0);
  stageCopy(from, to).commit();
  REQUIRE(::stat(to.c_str(), &after) == 0);
  CHECK(after.st_ino == before.st_ino);
  CHECK(readFile(to) == bytes);
  // As long, one byte different: copied.
  std::string changed = bytes;
  changed[bytes.size() / 2] = static_cast<char>(changed[bytes.size() / 2] ^ 1);
  stageCopy(writeTemp("copy-changed.bin", changed), to).commit();
  CHECK(readFile(to) == changed);
  stageCopy(writeTemp("copy-empty.bin", ""), to).commit();
  CHECK(readFile(to).empty());
  const std::string missing = test::tempPath("no-such-texture.png");
  CHECK_THROWS_WITH(stageCopy(missing, to).commit(), Catch::Contains(missing));
  CHECK(readFile(to).empty());
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(to).parent_path())) {
    CHECK(entry.path().filename().string().rfind("copy-target.bin.partial-", 0) == std::string::npos);
  }
}

TEST_CASE("a staged file appears only when committed, and is removed if never committed", "[export][file]") {
  const std::string path = writeTemp("staged.txt", "the old content");
  const std::string copied = writeTemp("staged-copy.txt", "the old copy");
  {
    StagedFile text = stageFile(path, [](std::ostream& out) { out << "the new content"; });
    StagedFile copy = stageCopy(path, copied);  // copies what is in place now: the old content
    CHECK(readFile(path) == "the old content");
    CHECK(readFile(copied) == "the old copy");
    copy.commit();
    text.commit();
    CHECK_THROWS_AS(text.commit(), std::logic_error);
  }
  CHECK(readFile(path) == "the new content");
  CHECK(readFile(copied) == "the old content");
  {
    const StagedFile dropped = stageFile(path, [](std::ostream& out) { out << "never placed"; });
  }
  CHECK(readFile(path) == "the new content");
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("staged", 0) == 0) CHECK(name.find(".partial-") == std::string::npos);
  }
}

TEST_CASE("a write that fails half-way leaves the old file as it was and no partial file", "[export][file]") {
  const std::string path = writeTemp("kept.txt", "the old content");
  const std::string big(std::size_t{6} << 20, 'x');
  CHECK_THROWS_WITH(writeFileAtomically(path, [&](std::ostream& out) {
                      out.write(big.data(), static_cast<std::streamsize>(big.size()));
                      throw std::runtime_error("the writer gave up");
                    }),
                    "the writer gave up");
  CHECK(readFile(path) == "the old content");
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path())) {
    CHECK(entry.path().filename().string().rfind("kept.txt.partial-", 0) == std::string::npos);
  }
}

// ---------------------------------------------------------------- OBJ

TEST_CASE("OBJ quads read back bit for bit", "[export][obj]") {
  for (const QuadMesh& m : {cube(), tube(5)}) {
    const std::string text = writeObj(m, false);
    CHECK_THAT(text, Contains("Arbor"));
    const QuadMesh back = readObj(text, "round.obj");
    REQUIRE(back.positions.size() == m.positions.size());
    CHECK(back.positions == m.positions);
    CHECK(back.normals == m.normals);
    for (std::size_t i = 0; i < m.uvw.size(); ++i) {
      CHECK(back.uvw[i].x == m.uvw[i].x);
      CHECK(back.uvw[i].y == m.uvw[i].y);
    }
    CHECK(back.quads == m.quads);
  }
}

TEST_CASE("OBJ is y up by default, z up on request, and both read back to Arbor's axes", "[export][obj]") {
  const QuadMesh m = tube(5);
  const auto firstLine = [](const std::string& text, const std::string& keyword) {
    const std::size_t at = text.find("\n" + keyword + " ");
    std::istringstream in(text.substr(at + keyword.size() + 2));
    glm::vec3 v;
    in >> v.x >> v.y >> v.z;
    return v;
  };
  const std::string yUp = writeObj(m, false), zUp = writeObj(m, false, Up::Z);
  CHECK_THAT(yUp, Contains("y up"));
  CHECK_THAT(zUp, Contains("z up"));
  // A rotation about x: Arbor's up (z) becomes y, its y becomes -z; normals turn with the points.
  CHECK(firstLine(yUp, "v") == glm::vec3(m.positions[0].x, m.positions[0].z, -m.positions[0].y));
  CHECK(firstLine(yUp, "vn") == glm::vec3(m.normals[0].x, m.normals[0].z, -m.normals[0].y));
  CHECK(firstLine(zUp, "v") == m.positions[0]);
  for (const std::string& text : {yUp, zUp}) {
    const QuadMesh back = readObj(text, "axes.obj");
    CHECK(back.positions == m.positions);
    CHECK(back.normals == m.normals);
    CHECK(back.quads == m.quads);
  }
}

TEST_CASE("OBJ triangles read back into the same quads", "[export][obj]") {
  const QuadMesh m = tube(5);
  const std::string text = writeObj(m, true);
  std::size_t faceLines = 0;
  for (std::size_t at = text.find("\nf "); at != std::string::npos; at = text.find("\nf ", at + 1)) ++faceLines;
  CHECK(faceLines == 2 * m.quads.size());
  const QuadMesh back = readObj(text, "triangles.obj");
  CHECK(back.positions == m.positions);
  CHECK(back.quads == m.quads);
  CHECK(triangulate(back) == triangulate(m));
}

TEST_CASE("OBJ keeps awkward floats exactly", "[export][obj]") {
  QuadMesh m = cube();
  m.positions[3] = {0.1f, 1.0f / 3.0f, -1e-7f};
  m.positions[5] = {123456.789f, 3.4e38f, 1.17549435e-38f};
  m.uvw[2] = {0.7f, 1e-20f, 0.0f};
  const QuadMesh back = readObj(writeObj(m, false), "awkward.obj");
  CHECK(back.positions == m.positions);
  CHECK(back.uvw[2].x == m.uvw[2].x);
  CHECK(back.uvw[2].y == m.uvw[2].y);
}

TEST_CASE("malformed OBJ names the file and line", "[export][obj]") {
  const std::string head = "# test\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                           "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n";
  CHECK(readObj(head + "f 1/1/1 2/2/2 3/3/3 4/4/4\n", "ok.obj").quads.size() == 1);
  CHECK_THROWS_WITH(readObj(head + "f 1/1/1 2/2/2 3/3/3 9/9/9\n", "bad.obj"), Contains("bad.obj:14") && Contains("vertex 9"));
  CHECK_THROWS_WITH(readObj(head + "f 1/1/1 2/2/2 3/3/3 4/4/x\n", "bad.obj"), Contains("bad.obj:14"));
  CHECK_THROWS_WITH(readObj(head + "f 1/1/1 2/2/2 3/3/3 4/3/4\n", "bad.obj"), Contains("bad.obj:14"));
  CHECK_THROWS_WITH(readObj(head + "f 1/1/1 2/2/2 3/3/3\n", "bad.obj"), Contains("bad.obj:14") && Contains("partner"));
  CHECK_THROWS_WITH(readObj("v 1 2\n", "bad.obj"), Contains("bad.obj:1"));
  CHECK_THROWS_WITH(readObj("v 1 2 3e\n", "bad.obj"), Contains("bad.obj:1"));
  CHECK_THROWS_WITH(readObj("\n\nl 1 2\n", "bad.obj"), Contains("bad.obj:3") && Contains("'l'"));
  CHECK_THROWS_WITH(readObj("v 0 0 0\nvn 0 0 1\n", "bad.obj"), Contains("bad.obj"));
}

// ---------------------------------------------------------------- glTF / GLB

TEST_CASE("GLB chunks are consistent and the buffer is y up", "[export][gltf]") {
  const QuadMesh m = cube();
  const Glb glb = splitGlb(writeGlb(m, "cube"));
  const auto& doc = glb.json;
  CHECK(doc["asset"]["version"] == "2.0");
  CHECK(doc["asset"]["generator"] == "Arbor");
  const auto& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
  for (const char* name : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "_RADIUS", "_LEVEL", "_FLIP"}) {
    INFO(name);
    CHECK(attributes.contains(name));
  }

  const auto positions = accessorFloats(doc, glb.binary, attributes["POSITION"], 3);
  REQUIRE(positions.size() == 3 * m.vertexCount());
  int atHeightTwo = 0;
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    const glm::vec3 p = m.positions[i];
    CHECK(positions[3 * i + 0] == p.x);
    CHECK(positions[3 * i + 1] == p.z);  // up
    CHECK(positions[3 * i + 2] == -p.y);
    if (p.z == 2.0f) atHeightTwo += positions[3 * i + 1] == 2.0f ? 1 : 0;
  }
  CHECK(atHeightTwo == 4);
  const auto& position = doc["accessors"][attributes["POSITION"].get<int>()];
  CHECK(position["min"] == nlohmann::json({-1.0, 0.0, -1.0}));
  CHECK(position["max"] == nlohmann::json({1.0, 2.0, 1.0}));

  const auto normals = accessorFloats(doc, glb.binary, attributes["NORMAL"], 3);
  const auto tangents = accessorFloats(doc, glb.binary, attributes["TANGENT"], 4);
  const auto flip = accessorFloats(doc, glb.binary, attributes["_FLIP"], 1);
  for (std::size_t i = 0; i < m.vertexCount(); ++i) {
    const glm::vec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    const glm::vec3 t(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
    CHECK(std::abs(glm::length(n) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::length(t) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::dot(n, t)) < 1e-6f);
    CHECK(std::abs(tangents[4 * i + 3]) == 1.0f);
    CHECK(n.y * m.normals[i].z > 0);  // the up component moved along with the positions
    CHECK(flip[i] == m.uvw[i].z);
  }
  const auto& indices = doc["accessors"][doc["meshes"][0]["primitives"][0]["indices"].get<int>()];
  CHECK(indices["componentType"] == 5125);
  CHECK(indices["count"] == 3 * 2 * m.quads.size());
}

TEST_CASE(".gltf embeds the same buffer as the GLB", "[export][gltf]") {
  const QuadMesh m = tube(4);
  const auto doc = nlohmann::json::parse(writeGltf(m, "tube"));
  const std::string uri = doc["buffers"][0]["uri"];
  const std::string prefix = "data:application/octet-stream;base64,";
  REQUIRE(uri.rfind(prefix, 0) == 0);
  const std::string embedded = decodeBase64(uri.substr(prefix.size()));
  CHECK(embedded.size() == doc["buffers"][0]["byteLength"]);
  const Glb glb = splitGlb(writeGlb(m, "tube"));
  CHECK(embedded == glb.binary.substr(0, embedded.size()));
  CHECK(doc["accessors"] == glb.json["accessors"]);
}

TEST_CASE("degenerate normals and tangents still export as unit, orthogonal vectors", "[export][gltf]") {
  QuadMesh m = cube();
  m.normals[0] = glm::vec3(0);
  m.tangents[1] = glm::vec3(0);
  m.tangents[2] = m.normals[2];  // along the normal: nothing left after Gram-Schmidt
  m.tangents[3] = glm::vec3(1, 0, 0) + m.normals[3] * 5.0f;
  const Glb glb = splitGlb(writeGlb(m, "cube"));
  const auto& attributes = glb.json["meshes"][0]["primitives"][0]["attributes"];
  const auto normals = accessorFloats(glb.json, glb.binary, attributes["NORMAL"], 3);
  const auto tangents = accessorFloats(glb.json, glb.binary, attributes["TANGENT"], 4);
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    const glm::vec3 t(tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]);
    CHECK(std::abs(glm::length(n) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::length(t) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::dot(n, t)) < 1e-6f);
  }
  // Vertex 0's replacement comes from its faces: it still points away from the cube's centre (y-up here).
  CHECK(glm::dot(glm::vec3(normals[0], normals[1], normals[2]), glm::vec3(-1, -1, 1)) > 0);
}

TEST_CASE("glTF export refuses a mesh it cannot describe", "[export][gltf]") {
  QuadMesh m = cube();
  m.radius.pop_back();
  CHECK_THROWS_AS(writeGlb(m, "short"), std::invalid_argument);
  CHECK_THROWS_AS(writeGltf(QuadMesh{}, "empty"), std::invalid_argument);
  QuadMesh nan = cube();
  nan.positions[2].x = std::nanf("");
  CHECK_THROWS_AS(writeGlb(nan, "nan"), std::invalid_argument);
}

TEST_CASE("the Khronos validator finds no errors in .gltf and .glb files", "[export][gltf][validator]") {
  struct Case {
    std::string file;
    QuadMesh mesh;
  };
  for (const Case& c : {Case{"cube", cube()}, Case{"tube", tube(6)}, Case{"tube-smooth", subdivide(tube(6), 2)},
                        Case{"open-tube", subdivide(tube(4, true), 1)}}) {
    for (const bool binary : {false, true}) {
      const std::string path = writeTemp(c.file + (binary ? ".glb" : ".gltf"),
                                         binary ? writeGlb(c.mesh, c.file) : writeGltf(c.mesh, c.file));
      const Run r = validate(path);
      INFO(r.output);
      CHECK(r.exitCode == 0);
      CHECK_THAT(r.output, Contains(": 0 errors"));
    }
  }
}

TEST_CASE("the validator script fails on a file with errors and on a missing file", "[export][gltf][validator]") {
  auto doc = nlohmann::json::parse(writeGltf(cube(), "cube"));
  doc["accessors"][0]["max"][1] = 100.0;  // no longer the largest y in the data
  const Run broken = validate(writeTemp("broken.gltf", doc.dump()));
  INFO(broken.output);
  CHECK(broken.exitCode == 1);
  CHECK_THAT(broken.output, Contains("ACCESSOR_MAX_MISMATCH"));
  const Run missing = validate(test::tempPath("no-such-file.glb"));
  INFO(missing.output);
  CHECK(missing.exitCode == 2);
}

// ---------------------------------------------------------------- subdivision

TEST_CASE("one level of Catmull-Clark turns the cube into 24 closed, outward quads", "[export][subdivide]") {
  const QuadMesh s = subdivide(cube(), 1);
  CHECK(s.quads.size() == 24);
  CHECK(s.vertexCount() == 8 + 12 + 6);
  requireClosedAndOriented(s);
  CHECK(normalsAgainstFaces(s) == 0);
  CHECK(s.openBoundary.empty());
  for (std::size_t i = 0; i < s.vertexCount(); ++i) {
    CHECK(std::abs(glm::length(s.normals[i]) - 1.0f) < 1e-5f);
    CHECK(std::abs(glm::length(s.tangents[i]) - 1.0f) < 1e-5f);
    CHECK(std::abs(glm::dot(s.normals[i], s.tangents[i])) < 1e-5f);
    // The limit surface of a cube lies strictly inside it.
    const glm::vec3 p = s.positions[i] - glm::vec3(0, 0, 1);
    CHECK(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 1.0f);
  }
}

TEST_CASE("two levels on the capped tube: 16x the quads, closed, oriented, attributes interpolated", "[export][subdivide]") {
  const QuadMesh t = tube(7);
  const QuadMesh s = subdivide(t, 2);
  CHECK(s.quads.size() == 16 * t.quads.size());
  requireClosedAndOriented(s);
  CHECK(normalsAgainstFaces(s) == 0);
  REQUIRE(s.level.size() == s.vertexCount());
  int lower = 0, upper = 0;
  for (std::size_t i = 0; i < s.vertexCount(); ++i) {
    CHECK(s.level[i] <= 1);
    (s.level[i] == 0 ? lower : upper) += 1;
    CHECK(s.radius[i] == Approx(kTubeRadius));
    CHECK(s.uvw[i].x >= 0.0f);
    CHECK(s.uvw[i].x <= 1.0f);
    // Along the tube's side the tangent still runs up the branch.
    if (s.positions[i].z > 1.5f && s.positions[i].z < 4.5f) CHECK(s.tangents[i].z > 0.99f);
  }
  CHECK(lower > 0);
  CHECK(upper > 0);
}

TEST_CASE("the middle ring of a long tube lands on the limit curve of its square", "[export][subdivide]") {
  // Far from the caps the surface is a tensor-product cubic B-spline, straight along z, so every cross
  // section is the closed B-spline of the square ring of radius R. Its point at a control vertex is
  // (P[-1] + 4 P[0] + P[1]) / 6 = 2R/3 from the axis; halfway between two it is
  // (P[-1] + 23 P[0] + 23 P[1] + P[2]) / 48 = (22/48) * sqrt(2) R = 0.6482 R. In between the radius stays
  // between those two. Rings 2..4 of 7 are regular (the caps' valence-3 corners are two rings away),
  // so the middle ring (z = 3) is exact up to float rounding.
  const int rings = 7;
  const float middle = 3 * kRingSpacing;
  const double atVertex = 2.0 / 3.0 * kTubeRadius;
  const double halfway = 22.0 / 48.0 * std::numbers::sqrt2 * kTubeRadius;
  const double tolerance = 1e-5;
  const QuadMesh s = subdivide(tube(rings), 2);
  int onRing = 0, onAxes = 0, onDiagonals = 0;
  for (const auto& p : s.positions) {
    if (std::abs(p.z - middle) > 1e-4f) continue;
    ++onRing;
    const double r = std::hypot(double{p.x}, double{p.y});
    CHECK(r >= halfway - tolerance);
    CHECK(r <= atVertex + tolerance);
    if (std::abs(p.x) < 1e-5f || std::abs(p.y) < 1e-5f) {
      ++onAxes;
      CHECK(r == Approx(atVertex).margin(tolerance));
    } else if (std::abs(std::abs(p.x) - std::abs(p.y)) < 1e-5f) {
      ++onDiagonals;
      CHECK(r == Approx(halfway).margin(tolerance));
    }
  }
  CHECK(onRing == 16);  // 4 ring edges, each split into 4 by two levels
  CHECK(onAxes == 4);
  CHECK(onDiagonals == 4);
}

TEST_CASE("an open base ring stays open, flat and in order", "[export][subdivide]") {
  const QuadMesh t = tube(4, true);
  for (const int levels : {1, 3}) {
    const QuadMesh s = subdivide(t, levels);
    REQUIRE(s.openBoundary.size() == t.openBoundary.size() << levels);
    const DirectedEdges edges = directedEdges(s);
    std::size_t boundaryEdges = 0;
    for (const auto& [edge, count] : edges) boundaryEdges += edges.count({edge.second, edge.first}) == 0 ? 1 : 0;
    CHECK(boundaryEdges == s.openBoundary.size());
    for (std::size_t i = 0; i < s.openBoundary.size(); ++i) {
      const std::uint32_t a = s.openBoundary[i], b = s.openBoundary[(i + 1) % s.openBoundary.size()];
      // The input ring follows its quads' winding along the hole, and so does the refined one.
      CHECK(edges.count({a, b}) == 1);
      CHECK(edges.count({b, a}) == 0);
      // Edge-only boundary interpolation keeps the ring on the ground instead of pulling it up the tube.
      CHECK(std::abs(s.positions[a].z) < 1e-6f);
    }
  }
}

TEST_CASE("subdivision refuses non-manifold and malformed meshes", "[export][subdivide]") {
  SECTION("three quads sharing one edge") {
    QuadMesh fan;
    for (int i = 0; i < 8; ++i) {
      const float a = static_cast<float>(i);
      addVertex(fan, {std::cos(a), std::sin(a), a}, {0, 0, 1}, {1, 0, 0}, {0, 0, 0}, 0.1f, 0);
    }
    fan.quads = {{0, 1, 2, 3}, {1, 0, 4, 5}, {0, 1, 6, 7}};
    CHECK_THROWS_WITH(subdivide(fan, 1), Contains("non-manifold") && Contains("3 faces"));
  }
  SECTION("two neighbours wound against each other") {
    QuadMesh flipped = cube();
    std::swap(flipped.quads[0][1], flipped.quads[0][3]);
    CHECK_THROWS_WITH(subdivide(flipped, 1), Contains("non-manifold"));
  }
  SECTION("what OpenSubdiv itself reports reaches the caller as an exception") {
    CHECK_THROWS_WITH(subdivide(QuadMesh{}, 1), Contains("OpenSubdiv") && Contains("no vertices"));
  }
  SECTION("indices and level counts OpenSubdiv would not check") {
    QuadMesh stray = cube();
    stray.quads[2][1] = 99;
    CHECK_THROWS_AS(subdivide(stray, 1), std::invalid_argument);
    CHECK_THROWS_AS(subdivide(cube(), 0), std::invalid_argument);
    CHECK_THROWS_AS(subdivide(cube(), 7), std::invalid_argument);
    QuadMesh notARing = tube(3, true);
    notARing.openBoundary = {0, 2, 1, 3};
    CHECK_THROWS_AS(subdivide(notARing, 1), std::invalid_argument);
  }
}

// ---------------------------------------------------------------- complete tree assets (issue 18)

namespace {

Skeleton growPreset(const std::string& name, int levels = 0) {
  GrowthOptions o;
  o.seed = 1;
  o.levels = levels;
  return generateSkeleton(test::loadPreset(name), o);
}

// A small opaque PNG (the validator decodes the images' headers), made by the project's own encoder.
std::string pngOf(int size, std::uint8_t grey) {
  Image image;
  image.width = image.height = size;
  image.rgba.assign(static_cast<std::size_t>(size * size * 4), grey);
  return encodePng(image);
}

AssetTextures someTextures() { return {pngOf(8, 100), pngOf(8, 128), pngOf(8, 200)}; }

}  // namespace

TEST_CASE("leaf cards: one per leaf from its base to its tip, facing as the leaf, in its kind's atlas cell", "[export][cards]") {
  std::vector<Leaf> leaves;
  for (std::uint8_t kind = 0; kind < 4; ++kind) {
    Leaf leaf;
    leaf.position = Vec3(kind, 1.0, 2.0);
    leaf.direction = glm::normalize(Vec3(0.3, 0.1, 1.0));
    leaf.normal = glm::normalize(glm::cross(leaf.direction, Vec3(1, 0, 0)));
    leaf.length = 0.1 + 0.01 * kind;
    leaf.width = 0.03;
    leaf.kind = kind;
    leaves.push_back(leaf);
  }
  const CardMesh cards = leafCards(leaves);
  REQUIRE(cards.quads.size() == leaves.size());
  REQUIRE(cards.positions.size() == 4 * leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    INFO("kind " << i);
    const auto& q = cards.quads[i];
    const glm::vec3 a = cards.positions[q[0]], b = cards.positions[q[1]], c = cards.positions[q[2]], d = cards.positions[q[3]];
    const glm::vec3 base = 0.5f * (a + b), tip = 0.5f * (c + d);
    CHECK(glm::distance(base, glm::vec3(leaves[i].position)) < 1e-6f);
    CHECK(glm::distance(tip, glm::vec3(leaves[i].position + leaves[i].direction * leaves[i].length)) < 1e-6f);
    CHECK(std::abs(glm::distance(a, b) - 2.0f * 0.03f / kLeafBladeShare[i]) < 1e-6f);
    // Counter-clockwise about the leaf's normal, and every corner carries it.
    const glm::vec3 face = glm::normalize(glm::cross(c - a, d - b));
    CHECK(glm::dot(face, glm::vec3(leaves[i].normal)) > 0.9999f);
    for (const std::uint32_t v : q) {
      CHECK(glm::dot(cards.normals[v], glm::vec3(leaves[i].normal)) > 0.9999f);
      // Inside the kind's cell of the 2 x 2 atlas; the tip at the cell's top (glTF's v grows down).
      const glm::vec2 cell = glm::vec2(static_cast<float>(i % 2), static_cast<float>(i / 2)) * 0.5f;
      const glm::vec2 t = cards.texcoords[v] - cell;
      CHECK(t.x >= 0.0f);
      CHECK(t.x <= 0.5f);
      CHECK(t.y >= 0.0f);
      CHECK(t.y <= 0.5f);
    }
    CHECK(cards.texcoords[q[2]].y < cards.texcoords[q[0]].y);
  }
}

TEST_CASE("branch cards: two crossed cards per segment, as wide as the branch, bark v running on", "[export][cards]") {
  const std::vector<ImpostorSegment> segments = {{Vec3(0, 0, 1), Vec3(0.5, 0, 2), 0.04, 0.03, 0.5, 1.5, 2},
                                                 {Vec3(0.5, 0, 2), Vec3(0.5, 0, 2), 0.03, 0.02, 1.5, 1.5, 2},  // zero length: none
                                                 {Vec3(0, 0, 0), Vec3(0, 0, 1), 0.05, 0.04, 0.0, 2.0, 3}};    // vertical
  const CardMesh cards = branchCards(segments);
  REQUIRE(cards.quads.size() == 4);
  for (std::size_t k = 0; k < cards.quads.size(); ++k) {
    const ImpostorSegment& s = segments[k < 2 ? 0 : 2];
    const auto& q = cards.quads[k];
    const glm::vec3 axis = glm::normalize(glm::vec3(s.to - s.from));
    const glm::vec3 lo = 0.5f * (cards.positions[q[0]] + cards.positions[q[1]]), hi = 0.5f * (cards.positions[q[2]] + cards.positions[q[3]]);
    CHECK(glm::distance(lo, glm::vec3(s.from) - axis * float(0.5 * s.fromRadius)) < 1e-6f);
    CHECK(glm::distance(hi, glm::vec3(s.to) + axis * float(0.5 * s.toRadius)) < 1e-6f);
    CHECK(std::abs(glm::distance(cards.positions[q[0]], cards.positions[q[1]]) - float(2 * s.fromRadius)) < 1e-6f);
    CHECK(std::abs(glm::distance(cards.positions[q[2]], cards.positions[q[3]]) - float(2 * s.toRadius)) < 1e-6f);
    CHECK(cards.texcoords[q[0]].y == float(s.fromV));
    CHECK(cards.texcoords[q[2]].y == float(s.toV));
    CHECK(std::abs(glm::dot(cards.normals[q[0]], axis)) < 1e-6f);
  }
  // The two cards of a segment are at right angles.
  CHECK(std::abs(glm::dot(cards.normals[cards.quads[0][0]], cards.normals[cards.quads[1][0]])) < 1e-6f);
}

TEST_CASE("bark tangents run along +u with the handedness glTF's normal maps need", "[export][gltf]") {
  const QuadMesh m = buildTree(growPreset("quaking-aspen", 2), BuildOptions{{}, false}).mesh.mesh;
  const Glb glb = splitGlb(writeGlb(m, "aspen"));
  const auto& attributes = glb.json["meshes"][0]["primitives"][0]["attributes"];
  const auto normals = accessorFloats(glb.json, glb.binary, attributes["NORMAL"], 3);
  const auto tangents = accessorFloats(glb.json, glb.binary, attributes["TANGENT"], 4);
  // dP/du and dP/dv of each quad's first triangle, in glTF's axes, checked at its corners away from the mirror lines.
  std::size_t checked = 0, along = 0, handed = 0;
  auto yUp = [](glm::vec3 v) { return glm::vec3(v.x, v.z, -v.y); };
  for (const auto& q : m.quads) {
    const glm::vec3 e1 = yUp(m.positions[q[1]] - m.positions[q[0]]), e2 = yUp(m.positions[q[2]] - m.positions[q[0]]);
    const glm::vec2 d1 = glm::vec2(m.uvw[q[1]] - m.uvw[q[0]]), d2 = glm::vec2(m.uvw[q[2]] - m.uvw[q[0]]);
    const float r = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(r) < 1e-6f) continue;
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / r, dPdv = (e2 * d1.x - e1 * d2.x) / r;
    const std::uint32_t v = q[0];
    if (std::abs(m.uvw[v].x - 0.5f) > 0.2f || m.level[v] != 1) continue;  // mirror lines at u = 0 and 1; joints on the trunk
    const glm::vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
    const glm::vec3 t(tangents[4 * v], tangents[4 * v + 1], tangents[4 * v + 2]);
    const float w = tangents[4 * v + 3];
    REQUIRE(std::abs(w) == 1.0f);
    ++checked;
    along += glm::dot(t, dPdu) > 0.0f ? 1 : 0;
    handed += glm::dot(glm::cross(n, t) * w, dPdv) < 0.0f ? 1 : 0;  // the bitangent points up the image, against v
  }
  CHECK(checked > 300);
  CHECK(along >= checked * 99 / 100);
  CHECK(handed >= checked * 99 / 100);
}

TEST_CASE("a complete asset: textures, cards, leaves shared by every level of detail, MSFT_lod, validator clean", "[export][gltf][validator]") {
  const Skeleton skeleton = growPreset("quaking-aspen", 3);
  TreeAssetOptions options;
  options.lods = 3;
  TreeAsset asset = makeTreeAsset(skeleton, "aspen", options);
  asset.textures = someTextures();
  REQUIRE(asset.lods.size() == 3);
  CHECK(asset.lods[0].meshedLevels == 3);
  CHECK(asset.lods[2].meshedLevels == 1);
  CHECK(asset.lods[1].bark->quads.size() < asset.lods[0].bark->quads.size());
  CHECK(asset.lods[2].branchCards.quads.size() > asset.lods[1].branchCards.quads.size());
  CHECK(asset.leaves.quads.size() == skeleton.leaves.size());

  const Glb glb = splitGlb(writeGlb(asset));
  const auto& doc = glb.json;
  CHECK(doc["extensionsUsed"] == nlohmann::json::array({"MSFT_lod"}));
  CHECK(doc["scenes"][0]["nodes"] == nlohmann::json::array({0}));
  CHECK(doc["nodes"][0]["extensions"]["MSFT_lod"]["ids"] == nlohmann::json::array({1, 2}));
  CHECK(doc["nodes"][0]["extras"]["MSFT_screencoverage"].size() == 3);
  CHECK(doc["images"].size() == 3);
  for (const auto& image : doc["images"]) CHECK(image["mimeType"] == "image/png");
  std::map<std::string, nlohmann::json> materials;
  for (const auto& m : doc["materials"]) materials[m["name"]] = m;
  REQUIRE(materials.count("bark") + materials.count("branch_cards") + materials.count("leaves") == 3);
  CHECK(materials["bark"].contains("normalTexture"));
  CHECK(materials["bark"]["pbrMetallicRoughness"].contains("baseColorTexture"));
  CHECK(materials["leaves"]["alphaMode"] == "MASK");
  CHECK(materials["leaves"]["doubleSided"] == true);
  CHECK(materials["branch_cards"]["doubleSided"] == true);
  // Level 0 meshes every level: its only cards are the twigs the mesh could not join near their attachment (this
  // tree has some); the leaves, last, are the same accessors in all three.
  REQUIRE_FALSE(asset.lods[0].fakedStems.empty());
  CHECK(doc["meshes"][0]["primitives"].size() == 3);
  CHECK(doc["meshes"][2]["primitives"].size() == 3);
  CHECK(doc["meshes"][0]["primitives"][2] == doc["meshes"][2]["primitives"][2]);
  CHECK(doc["meshes"][0]["primitives"][1] != doc["meshes"][2]["primitives"][1]);

  for (const bool binary : {false, true}) {
    const std::string path = writeTemp(std::string("aspen-asset") + (binary ? ".glb" : ".gltf"), binary ? writeGlb(asset) : writeGltf(asset));
    const Run r = validate(path);
    INFO(r.output);
    CHECK(r.exitCode == 0);
    CHECK_THAT(r.output, Contains(": 0 errors, 0 warnings"));
  }
}

TEST_CASE("OBJ of an asset: cards as objects after the surface, read back as the surface alone", "[export][obj]") {
  const Skeleton skeleton = growPreset("palm");
  const TreeAsset asset = makeTreeAsset(skeleton, "palm", TreeAssetOptions{});
  const QuadMesh& bark = *asset.lods[0].bark;
  std::ostringstream out;
  writeObj(bark, false, out, Up::Y, "palm.mtl");
  ObjCounts counts{bark.vertexCount(), bark.vertexCount(), bark.vertexCount()};
  if (!asset.lods[0].branchCards.empty()) writeObjCards(asset.lods[0].branchCards, "branch_cards", "branch_cards", counts, out);
  writeObjCards(asset.leaves, "leaves", "leaves", counts, out);
  const std::string text = out.str();
  std::ostringstream once;
  writeObjAsset(bark, leftOutSegments(skeleton, asset.lods[0].meshedLevels, asset.lods[0].fakedStems), skeleton.leaves, false, once, Up::Y, "palm.mtl");
  CHECK(once.str() == text);  // one pass over all three parts writes what the three calls write
  // Leaves of every kind, mixed, and kinds past the atlas's four (drawn as the last): the texture coordinates
  // of the cards made while printing are numbered as writeObjCards numbers leafCards' (kinds share corners).
  std::vector<Leaf> mixed = skeleton.leaves;
  for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i].kind = static_cast<std::uint8_t>((i * 5 + i / 7) % 9);
  std::ostringstream mixedParts, mixedOnce;
  writeObj(bark, false, mixedParts, Up::Y, "palm.mtl");
  ObjCounts mixedCounts{bark.vertexCount(), bark.vertexCount(), bark.vertexCount()};
  writeObjCards(leafCards(mixed), "leaves", "leaves", mixedCounts, mixedParts);
  writeObjAsset(bark, {}, mixed, false, mixedOnce, Up::Y, "palm.mtl");
  CHECK(mixedOnce.str() == mixedParts.str());
  // The leaves' lines printed ahead (while a tree file's bark is meshed) give the same text; printed for the
  // other axis they are refused.
  const auto notYet = [] { return false; };
  const auto enough = [] { return true; };
  std::ostringstream ahead, numberedOnly, wrongAxis;
  writeObjAsset(bark, {}, *printObjLeafLines(mixed, Up::Y, notYet), false, ahead, Up::Y, "palm.mtl");
  CHECK(ahead.str() == mixedParts.str());
  writeObjAsset(bark, {}, *printObjLeafLines(mixed, Up::Y, enough), false, numberedOnly, Up::Y, "palm.mtl");
  CHECK(numberedOnly.str() == mixedParts.str());
  CHECK_THROWS_AS(writeObjAsset(bark, {}, *printObjLeafLines(mixed, Up::Z, notYet), false, wrongAxis, Up::Y, ""), std::invalid_argument);
  // Cards sharing corners are not what the writer numbers: refused, not written wrong.
  CardMesh shared = leafCards({mixed[0], mixed[1]});
  shared.quads[1][0] = shared.quads[0][3];
  ObjCounts sharedCounts;
  std::ostringstream refused;
  CHECK_THROWS_AS(writeObjCards(shared, "leaves", "", sharedCounts, refused), std::invalid_argument);
  CHECK_THAT(text, Contains("\nmtllib palm.mtl\nusemtl bark\n") && Contains("\no leaves\nusemtl leaves\n"));
  std::size_t faces = 0;
  for (std::size_t at = text.find("\nf "); at != std::string::npos; at = text.find("\nf ", at + 1)) ++faces;
  CHECK(faces == bark.quads.size() + asset.lods[0].branchCards.quads.size() + asset.leaves.quads.size());
  const QuadMesh back = readObj(text, "palm.obj");
  CHECK(back.quads == bark.quads);
  CHECK(back.positions.size() == bark.positions.size());

  // Every card corner resolves to its own position, texture coordinate (OBJ's v up the image) and normal, though
  // the cards write each distinct texture coordinate and normal once.
  std::vector<glm::vec3> v, vn;
  std::vector<glm::vec2> vt;
  std::vector<std::array<std::array<long, 3>, 4>> cardFaces;
  bool inCards = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "o") inCards = true;
    float x = 0, y = 0, z = 0;
    if (key == "v" && words >> x >> y >> z) v.emplace_back(x, y, z);
    if (key == "vn" && words >> x >> y >> z) vn.emplace_back(x, y, z);
    if (key == "vt" && words >> x >> y) vt.emplace_back(x, y);
    if (key == "f" && inCards) {
      std::array<std::array<long, 3>, 4> face{};
      for (auto& corner : face) {
        std::string c;
        words >> c;
        REQUIRE(std::sscanf(c.c_str(), "%ld/%ld/%ld", &corner[0], &corner[1], &corner[2]) == 3);
      }
      cardFaces.push_back(face);
    }
  }
  const std::size_t cardCorners = asset.lods[0].branchCards.positions.size() + asset.leaves.positions.size();
  CHECK(v.size() == bark.vertexCount() + cardCorners);
  CHECK(vt.size() < bark.vertexCount() + cardCorners / 2);  // leaves share their atlas corners
  CHECK(vn.size() <= bark.vertexCount() + cardCorners / 4);  // one normal a card at most
  REQUIRE(cardFaces.size() == asset.lods[0].branchCards.quads.size() + asset.leaves.quads.size());
  std::size_t mismatches = 0, face = 0;
  std::size_t firstVertex = bark.vertexCount();
  for (const CardMesh* cards : {&asset.lods[0].branchCards, &asset.leaves}) {
    for (const auto& quad : cards->quads) {
      for (std::size_t k = 0; k < 4; ++k) {
        const auto& [pi, ti, ni] = cardFaces[face][k];
        const std::uint32_t c = quad[k];
        const glm::vec3 p = cards->positions[c], n = cards->normals[c];
        mismatches += static_cast<std::size_t>(pi) != firstVertex + c + 1;
        mismatches += v[static_cast<std::size_t>(pi - 1)] != glm::vec3(p.x, p.z, -p.y);
        mismatches += vn[static_cast<std::size_t>(ni - 1)] != glm::vec3(n.x, n.z, -n.y);
        mismatches += vt[static_cast<std::size_t>(ti - 1)] != glm::vec2(cards->texcoords[c].x, 1.0f - cards->texcoords[c].y);
      }
      ++face;
    }
    firstVertex += cards->positions.size();
  }
  CHECK(mismatches == 0);
  const std::string mtl = writeMtl("c.png", "n.png", "a.png");
  CHECK_THAT(mtl, Contains("newmtl bark") && Contains("map_Kd c.png") && Contains("map_Bump -bm 1 n.png") &&
                      Contains("newmtl leaves") && Contains("map_d a.png"));
}

TEST_CASE("OBJ of an asset in one pass: the same text as its parts in turn, over many blocks, without materials", "[export][obj]") {
  const Skeleton skeleton = growPreset("black-tupelo", 3);
  TreeAssetOptions options;
  options.mesh.levels = 2;  // level 2 becomes branch cards
  const TreeAsset asset = makeTreeAsset(skeleton, "tupelo", options);
  const QuadMesh& bark = *asset.lods[0].bark;
  REQUIRE(asset.lods[0].branchCards.positions.size() > 8192);  // more lines than one printing block
  REQUIRE(asset.leaves.positions.size() > 8192);
  for (const bool triangles : {false, true}) {
    std::ostringstream parts, once;
    writeObj(bark, triangles, parts, Up::Z);
    ObjCounts counts{bark.vertexCount(), bark.vertexCount(), bark.vertexCount()};
    writeObjCards(asset.lods[0].branchCards, "branch_cards", "", counts, parts, Up::Z);
    writeObjCards(asset.leaves, "leaves", "", counts, parts, Up::Z);
    writeObjAsset(bark, leftOutSegments(skeleton, asset.lods[0].meshedLevels, asset.lods[0].fakedStems), skeleton.leaves, triangles, once, Up::Z, "");
    CHECK(once.str() == parts.str());
    // Leaves' lines printed ahead, over several blocks, and stopped part way (after the first block).
    std::ostringstream ahead, partWay;
    writeObjAsset(bark, leftOutSegments(skeleton, asset.lods[0].meshedLevels, asset.lods[0].fakedStems),
                  *printObjLeafLines(skeleton.leaves, Up::Z, [] { return false; }), triangles, ahead, Up::Z, "");
    CHECK(ahead.str() == parts.str());
    int blocks = 0;
    writeObjAsset(bark, leftOutSegments(skeleton, asset.lods[0].meshedLevels, asset.lods[0].fakedStems),
                  *printObjLeafLines(skeleton.leaves, Up::Z, [&] { return ++blocks > 2; }), triangles, partWay, Up::Z, "");
    CHECK(partWay.str() == parts.str());
    CHECK(once.str().find("usemtl") == std::string::npos);
  }
  // Every card corner reads back as its own texture coordinate and normal through the shared vt and vn lines
  // (tens of thousands of distinct leaf normals: the dedup table grows many times).
  std::ostringstream file;
  writeObjAsset(bark, leftOutSegments(skeleton, asset.lods[0].meshedLevels, asset.lods[0].fakedStems), skeleton.leaves, false, file, Up::Z, "");  // the tree's own axes
  std::vector<glm::vec2> vt;
  std::vector<glm::vec3> vn;
  std::vector<std::array<std::uint64_t, 12>> faces;  // v/vt/vn of the four corners
  std::istringstream lines(file.str());
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("vt ", 0) == 0) {
      glm::vec2 t;
      REQUIRE(std::sscanf(line.c_str(), "vt %f %f", &t.x, &t.y) == 2);
      vt.push_back(t);
    } else if (line.rfind("vn ", 0) == 0) {
      glm::vec3 n;
      REQUIRE(std::sscanf(line.c_str(), "vn %f %f %f", &n.x, &n.y, &n.z) == 3);
      vn.push_back(n);
    } else if (line.rfind("f ", 0) == 0 && line.find('/') != std::string::npos) {
      std::array<std::uint64_t, 12> f{};
      if (std::sscanf(line.c_str(), "f %lu/%lu/%lu %lu/%lu/%lu %lu/%lu/%lu %lu/%lu/%lu", &f[0], &f[1], &f[2], &f[3], &f[4], &f[5], &f[6], &f[7],
                      &f[8], &f[9], &f[10], &f[11]) == 12)
        faces.push_back(f);
    }
  }
  const std::size_t barkVertices = bark.vertexCount();
  std::size_t cardCorners = 0, wrong = 0;
  for (const std::array<std::uint64_t, 12>& f : faces) {
    if (f[0] <= barkVertices) continue;  // a bark quad
    for (int k = 0; k < 4; ++k) {
      const std::uint64_t v = f[3 * k] - 1 - barkVertices;
      const bool leaf = v >= asset.lods[0].branchCards.positions.size();
      const CardMesh& cards = leaf ? asset.leaves : asset.lods[0].branchCards;
      const std::size_t corner = leaf ? v - asset.lods[0].branchCards.positions.size() : v;
      const glm::vec2 t = vt[f[3 * k + 1] - 1];
      const glm::vec3 n = vn[f[3 * k + 2] - 1];
      wrong += (t != glm::vec2(cards.texcoords[corner].x, 1.0f - cards.texcoords[corner].y) || n != cards.normals[corner]) ? 1 : 0;
      ++cardCorners;
    }
  }
  CHECK(cardCorners == asset.lods[0].branchCards.positions.size() + asset.leaves.positions.size());
  CHECK(wrong == 0);
  CHECK(vn.size() - barkVertices > 8192);

  std::ostringstream noCards, barkOnly;
  writeObjAsset(bark, {}, std::vector<Leaf>{}, false, noCards, Up::Y, "");
  writeObj(bark, false, barkOnly, Up::Y);
  CHECK(noCards.str() == barkOnly.str());
}

TEST_CASE("wind animation: every part has one morph target per keyframe, one looping channel per level of detail, validator clean", "[export][gltf][validator][wind]") {
  const Skeleton skeleton = growPreset("quaking-aspen", 3);
  TreeAssetOptions options;
  options.lods = 2;
  options.wind.strength = 1.0;
  options.windFrames = 6;
  const TreeAsset asset = makeTreeAsset(skeleton, "aspen", options);
  REQUIRE(asset.windPeriod == Approx(4.0));
  const Glb glb = splitGlb(writeGlb(asset));
  const auto& doc = glb.json;
  for (const auto& mesh : doc["meshes"]) {
    CHECK(mesh["weights"].size() == 6);
    for (const auto& primitive : mesh["primitives"]) CHECK(primitive["targets"].size() == 6);
  }
  // The bark's first pose equals the wind function at time 0 on the cage (no subdivision here).
  const TreeMesh cage = buildTree(skeleton, BuildOptions{{}, false}).mesh;
  const auto points = meshWindPoints(skeleton, cage);
  const auto pose = accessorFloats(doc, glb.binary, doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"], 3);
  double worst = 0.0, largest = 0.0;
  for (std::size_t v = 0; v < cage.mesh.vertexCount(); ++v) {
    const glm::vec3 d = windOffset(cage.mesh.positions[v], points[v], options.wind, windHeight(skeleton), windPhase(skeleton), 0.0);
    const glm::vec3 stored(pose[3 * v], -pose[3 * v + 2], pose[3 * v + 1]);  // glTF's y up back to z up
    worst = std::max(worst, static_cast<double>(glm::distance(d, stored)));
    largest = std::max(largest, static_cast<double>(glm::length(d)));
  }
  CHECK(worst < 1e-6);
  CHECK(largest > 0.05);
  const auto& animation = doc["animations"][0];
  CHECK(animation["channels"].size() == 2);
  CHECK(animation["samplers"][0]["interpolation"] == "LINEAR");
  const auto times = accessorFloats(doc, glb.binary, animation["samplers"][0]["input"], 1);
  const auto weights = accessorFloats(doc, glb.binary, animation["samplers"][0]["output"], 1);
  REQUIRE(times.size() == 7);
  CHECK(times.back() == Approx(4.0));
  REQUIRE(weights.size() == 7 * 6);
  for (std::size_t k = 0; k < 7; ++k)
    for (std::size_t j = 0; j < 6; ++j) CHECK(weights[6 * k + j] == (j == k % 6 ? 1.0f : 0.0f));  // the loop ends on pose 0

  const Run r = validate(writeTemp("aspen-wind.glb", writeGlb(asset)));
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK_THAT(r.output, Contains(": 0 errors, 0 warnings"));
}
