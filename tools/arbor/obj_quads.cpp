#include "obj_quads.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

#include "common/input_error.hpp"
#include "export/obj_export.hpp"
#include "common/input_file.hpp"
#include "growth/tree_limits.hpp"

namespace arbor::cli {

namespace {

std::string_view nextWord(std::string_view& line) {
  std::size_t begin = 0;
  while (begin < line.size() && (line[begin] == ' ' || line[begin] == '\t' || line[begin] == '\r')) ++begin;
  std::size_t end = begin;
  while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
  const std::string_view word = line.substr(begin, end - begin);
  line.remove_prefix(end);
  return word;
}

struct LineError {
  const std::string& file;
  std::size_t line;
  [[noreturn]] void operator()(const std::string& message) const {
    throw InputError(file, "line " + std::to_string(line), message);
  }
};

double number(std::string_view word, const LineError& fail) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), x);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(x) || std::fabs(x) > 3.0e38)
    fail("'" + std::string(word) + "' is not a finite number within float range");
  return x;
}

// "i", "i/t", "i//n" or "i/t/n"; negative i counts back from the last vertex so far (OBJ's relative form).
std::uint32_t vertexIndex(std::string_view word, std::size_t vertices, const LineError& fail) {
  const std::string_view head = word.substr(0, word.find('/'));
  long long i = 0;
  const auto [end, ec] = std::from_chars(head.data(), head.data() + head.size(), i);
  if (ec != std::errc() || end != head.data() + head.size() || i == 0)
    fail("'" + std::string(word) + "' is not a vertex index (1-based, or negative counting back)");
  const long long index = i > 0 ? i - 1 : static_cast<long long>(vertices) + i;
  if (index < 0 || index >= static_cast<long long>(vertices))
    fail("vertex index " + std::to_string(i) + " is out of range: " + std::to_string(vertices) + " vertices so far");
  return static_cast<std::uint32_t>(index);
}

}  // namespace

QuadMesh parseObjQuads(const std::string& text, const std::string& file) {
  requireText(text, file);
  QuadMesh mesh;
  std::size_t lineNumber = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    const LineError fail{file, lineNumber};
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    const std::string_view keyword = nextWord(line);
    // Arbor's leaf and branch cards follow the tree's surface; the check is about the surface.
    if (keyword == "o" && isObjCardObject(nextWord(line))) break;
    if (keyword.empty() || keyword == "vt" || keyword == "vn" || keyword == "o" || keyword == "g" || keyword == "s" ||
        keyword == "usemtl" || keyword == "mtllib")
      continue;
    if (keyword == "v") {
      glm::vec3 p;
      for (int k = 0; k < 3; ++k) {
        const std::string_view w = nextWord(line);
        if (w.empty()) fail("a vertex needs three coordinates");
        p[k] = static_cast<float>(number(w, fail));
      }
      if (const std::string_view w = nextWord(line); !w.empty()) number(w, fail);  // an optional weight
      if (!nextWord(line).empty()) fail("a vertex has at most four numbers (x y z [w])");
      if (mesh.positions.size() >= 0xffffffffu) fail("too many vertices");
      mesh.positions.push_back(p);
      continue;
    }
    if (keyword == "f") {
      std::array<std::uint32_t, 4> quad{};
      std::size_t corners = 0;
      for (std::string_view w = nextWord(line); !w.empty(); w = nextWord(line)) {
        if (corners == 4) fail("a face with more than four corners; only quads are checked");
        quad[corners++] = vertexIndex(w, mesh.positions.size(), fail);
      }
      if (corners != 4) fail("a face with " + std::to_string(corners) + " corners; only quads are checked");
      for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
          if (quad[i] == quad[j]) fail("a quad uses vertex " + std::to_string(quad[i] + 1) + " twice");
      if (mesh.quads.size() >= TreeLimits{}.quads)
        throw LimitError(file + ": more than " + std::to_string(TreeLimits{}.quads) + " quads, the mesh limit");
      mesh.quads.push_back(quad);
      continue;
    }
    fail("'" + std::string(keyword) + "' is not supported; allowed: v, f (quads), vt, vn, o, g, s, usemtl, mtllib, #");
  }
  if (mesh.quads.empty()) throw InputError(file, "(file)", "no quads (f lines with four corners) in the file");
  return mesh;
}

QuadMesh readObjQuads(const std::string& path) { return parseObjQuads(readInputFile(path, kMaxObjBytes), path); }

}  // namespace arbor::cli
