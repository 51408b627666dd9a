#include "obj_export.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <charconv>
#include <cstdint>
#include <exception>
#include <initializer_list>
#include <limits>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "common/huge_page_blocks.hpp"
#include "export_checks.hpp"

namespace arbor {

namespace {

// Shortest text that reads back as the same float, so a write/read round trip is exact.
void appendFloat(char*& out, float x) { out = std::to_chars(out, out + 24, x).ptr; }

void appendLine(char*& out, const char* keyword, std::initializer_list<float> values) {
  while (*keyword != '\0') *out++ = *keyword++;
  for (const float x : values) {
    *out++ = ' ';
    appendFloat(out, x);
  }
  *out++ = '\n';
}

void appendIndex(char*& out, std::uint64_t index) { out = std::to_chars(out, out + 24, index + 1).ptr; }  // OBJ counts from 1

template <std::size_t N>
void appendFace(char*& out, const std::array<std::uint32_t, N>& corners) {
  *out++ = 'f';
  for (const std::uint32_t v : corners) {
    *out++ = ' ';
    char* start = out;
    appendIndex(out, v);
    const std::size_t digits = static_cast<std::size_t>(out - start);
    for (int k = 0; k < 2; ++k) {
      *out++ = '/';
      std::memcpy(out, start, digits);
      out += digits;
    }
  }
  *out++ = '\n';
}

// ---- reading ----

struct Reader {
  const std::string& file;
  std::size_t line = 0;

  [[noreturn]] void fail(const std::string& message) const {
    throw std::runtime_error(file + ":" + std::to_string(line) + ": " + message);
  }

  float number(std::string_view word) const {
    float x = 0;
    const auto result = std::from_chars(word.data(), word.data() + word.size(), x);
    if (result.ec != std::errc() || result.ptr != word.data() + word.size()) {
      fail("'" + std::string(word) + "' is not a number");
    }
    return x;
  }

  // One face corner "a/a/a" as a 0-based vertex index.
  std::uint32_t corner(std::string_view word) const {
    std::uint64_t parts[3] = {0, 0, 0};
    const char* p = word.data();
    const char* end = word.data() + word.size();
    for (int i = 0; i < 3; ++i) {
      const auto result = std::from_chars(p, end, parts[i]);
      const bool separatorOk = i < 2 ? (result.ptr != end && *result.ptr == '/') : result.ptr == end;
      if (result.ec != std::errc() || !separatorOk || parts[i] == 0) {
        fail("face corner '" + std::string(word) + "' is not v/vt/vn with 1-based indices");
      }
      p = result.ptr + 1;
    }
    if (parts[0] != parts[1] || parts[0] != parts[2]) {
      fail("face corner '" + std::string(word) + "' uses different v, vt and vn indices; Arbor writes one per vertex");
    }
    if (parts[0] > std::numeric_limits<std::uint32_t>::max()) fail("face corner '" + std::string(word) + "' is too large");
    return static_cast<std::uint32_t>(parts[0] - 1);
  }
};

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> result;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) result.push_back(line.substr(start, i - start));
  }
  return result;
}

using Triangle = std::array<std::uint32_t, 3>;
using Quad = std::array<std::uint32_t, 4>;

// Undoes arbor::triangulate: the partner runs the shared diagonal backwards, and its third corner goes
// between the diagonal's ends, which gives back the quad starting where the first triangle starts.
std::optional<Quad> joinTriangles(const Triangle& first, const Triangle& second) {
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t a = first[i], b = first[(i + 1) % 3];
    for (int j = 0; j < 3; ++j) {
      if (second[j] != b || second[(j + 1) % 3] != a) continue;
      const std::uint32_t apex = second[(j + 2) % 3];
      if (apex == first[0] || apex == first[1] || apex == first[2]) return std::nullopt;
      Quad quad{};
      int k = 0;
      for (int c = 0; c < 3; ++c) {
        quad[k++] = first[c];
        if (c == i) quad[k++] = apex;
      }
      return quad;
    }
  }
  return std::nullopt;
}

}  // namespace

namespace {

// Lines printed into a buffer of room for the longest ones, untouched past what was written (pages are touched only
// as written).
struct PrintedText {
  HugePageBlock data;
  std::size_t size = 0;
};

// Prints lines [begin, end) of one section at the pointer (at most kLineMax characters each), moving it past them.
using LinePrinter = std::function<void(char*& out, std::size_t begin, std::size_t end)>;

// A printer of one line at a time.
template <typename PrintLine>
LinePrinter eachLine(PrintLine line) {
  return [line](char*& out, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) line(out, i);
  };
}

// What one part of an OBJ file holds: the statements before its lines, how many v, vt, vn and f lines, and how to
// print them. The printers own (share) what they read, so a part outlives the function that made it.
struct ObjPart {
  std::string preamble;
  std::size_t count[4] = {0, 0, 0, 0};  // v, vt, vn, f
  LinePrinter print[4];
  const std::vector<PrintedText>* printed[4] = {};  // a section's first lines, printed ahead of the writing in blocks
  std::size_t printedLines[4] = {0, 0, 0, 0};        // how many lines those blocks hold
};

// The longest line: a quad's four v/vt/vn corners of 20-digit numbers; a v, vt or vn line, at most three floats of
// at most 15 characters each.
constexpr std::size_t kLineMax = 2 + 4 * (1 + 3 * 20 + 2) + 1;
constexpr std::size_t kNumbersLineMax = 3 + 3 * (1 + 15) + 1;

// Room for half a megabyte of a block's longest possible lines (10,700 number lines, 2,000 faces), four blocks to a
// huge page (a fresh 4 KiB page each cost a small file's printing more than its numbers).
constexpr std::size_t kBlockBytes = kHugePageBlockBytes;
constexpr std::size_t kBlockLines[2] = {kBlockBytes / kNumbersLineMax, kBlockBytes / kLineMax};  // numbers, faces
// A section shorter than four full blocks is still split four ways (down to this many lines a block), so a small
// file's printing is shared by every core as a large one's is.
constexpr std::size_t kBlockLinesLeast = 1024;

// Lines [begin, end) of a section into `out`, given room for a block's longest lines the first time.
void printBlock(const LinePrinter& print, std::size_t begin, std::size_t end, PrintedText& out) {
  if (!out.data) out.data = hugePageBlock();
  char* p = out.data.get();
  print(p, begin, end);
  out.size = static_cast<std::size_t>(p - out.data.get());
}

// The parts in order. Printing the numbers is most of the work (a tree's OBJ is tens of megabytes): blocks of lines
// are printed on every core in turn while this thread writes them out in file order, all parts in one pass (each
// pass drains the cores at its end).
void writeParts(const std::vector<ObjPart>& parts, std::ostream& stream) {
  struct Block {
    std::size_t part;
    int section;  // 0 v, 1 vt, 2 vn, 3 f
    std::size_t begin, end;
    const PrintedText* ahead = nullptr;  // printed before the writing began
  };
  std::vector<Block> blocks;
  for (std::size_t part = 0; part < parts.size(); ++part)
    for (int section = 0; section < 4; ++section) {
      if (const std::vector<PrintedText>* ahead = parts[part].printed[section])
        for (const PrintedText& text : *ahead) blocks.push_back({part, section, 0, 0, &text});
      const std::size_t left = parts[part].count[section] - parts[part].printedLines[section];
      const std::size_t lines = std::clamp(left / 4 + 1, kBlockLinesLeast, kBlockLines[section == 3 ? 1 : 0]);
      for (std::size_t i = parts[part].printedLines[section]; i < parts[part].count[section]; i += lines)
        blocks.push_back({part, section, i, std::min(parts[part].count[section], i + lines)});
    }
  using Text = PrintedText;
  auto print = [&](const Block& b, Text& out) {
    if (!b.ahead) printBlock(parts[b.part].print[b.section], b.begin, b.end, out);
  };
  std::size_t preambles = 0;  // parts whose preamble is out
  auto preamblesUpTo = [&](std::size_t part) {
    for (; preambles <= part && preambles < parts.size(); ++preambles)
      stream.write(parts[preambles].preamble.data(), static_cast<std::streamsize>(parts[preambles].preamble.size()));
  };

  // Workers print blocks at most `window` ahead of the writer into buffers it hands back: a few megabytes in
  // use whatever the file's size, each page touched once (fresh pages cost more than printing on a VM).
  const unsigned cores = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  const std::size_t workerCount = std::min<std::size_t>(cores, blocks.size());
  const std::size_t window = 2 * workerCount + 2;
  std::vector<Text> text(blocks.size());
  std::vector<char> printed(blocks.size(), 0);
  std::vector<Text> spare;
  std::size_t written = 0;
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<std::size_t> next{0};
  bool stopped = false;        // the writer failed (a full disk) or a worker did: the workers stop
  std::exception_ptr failure;  // a worker's, rethrown by the writer
  auto work = [&] {
    try {
      for (std::size_t i = next++; i < blocks.size(); i = next++) {
        Text out;
        {
          std::unique_lock<std::mutex> lock(mutex);
          ready.wait(lock, [&] { return stopped || i < written + window; });
          if (stopped) return;
          if (!spare.empty()) {
            out = std::move(spare.back());
            spare.pop_back();
          }
        }
        print(blocks[i], out);
        const std::lock_guard<std::mutex> lock(mutex);
        text[i] = std::move(out);
        printed[i] = 1;
        ready.notify_all();
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      failure = std::current_exception();
      stopped = true;
      ready.notify_all();
    }
  };
  // The workers stopped and joined however the writer leaves: a thread still running when its std::thread is
  // destroyed ends the process (a write failing half-way aborted instead of reporting the error).
  struct Workers {
    std::vector<std::thread> threads;
    std::mutex& mutex;
    std::condition_variable& ready;
    bool& stopped;
    ~Workers() {
      {
        const std::lock_guard<std::mutex> lock(mutex);
        stopped = true;
      }
      ready.notify_all();
      for (std::thread& t : threads) t.join();
    }
  } workers{{}, mutex, ready, stopped};
  for (std::size_t w = 0; w < workerCount; ++w) workers.threads.emplace_back(work);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    Text out;
    {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait(lock, [&] { return printed[i] != 0 || failure; });
      if (failure) std::rethrow_exception(failure);
      out = std::move(text[i]);
    }
    preamblesUpTo(blocks[i].part);
    const Text& lines = blocks[i].ahead ? *blocks[i].ahead : out;
    stream.write(lines.data.get(), static_cast<std::streamsize>(lines.size));
    const std::lock_guard<std::mutex> lock(mutex);
    written = i + 1;
    spare.push_back(std::move(out));
    ready.notify_all();
  }
  preamblesUpTo(parts.size());
}

// A position or normal line in the file's axes.
void appendAxes(char*& out, const char* keyword, const glm::vec3& p, Up up) {
  const glm::vec3 q = up == Up::Y ? glm::vec3(p.x, p.z, -p.y) : p;
  appendLine(out, keyword, {q.x, q.y, q.z});
}

void appendCorner(char*& out, std::uint64_t v, std::uint64_t vt, std::uint64_t vn) {
  *out++ = ' ';
  appendIndex(out, v);
  *out++ = '/';
  appendIndex(out, vt);
  *out++ = '/';
  appendIndex(out, vn);
}

// Numbers values by their distinct values, first seen first: cards repeat their atlas corners and every corner of
// a card has the card's normal, so each is written once. Most repeats are of the value before or the one four
// before (the same corner of the card before): those are found without hashing; the rest in an open-addressed
// table of indices into the distinct values (a node per value of a willow's leaves was a tenth of its export).
template <typename T>
class Distinct {
 public:
  std::uint32_t add(const T& value) {
    for (const std::size_t back : {std::size_t{1}, std::size_t{4}}) {
      const Recent& r = recent_[(added_ - back) % 4];
      if (added_ >= back && same(r.value, value)) return remember(value, r.index);
    }
    std::size_t slot = slotOf(value);
    if (table_[slot] == kEmpty) {
      if (2 * (values_.size() + 1) > table_.size()) {
        table_.assign(2 * table_.size(), kEmpty);
        for (std::uint32_t d = 0; d < values_.size(); ++d) table_[slotOf(values_[d])] = d;
        slot = slotOf(value);
      }
      table_[slot] = static_cast<std::uint32_t>(values_.size());
      values_.push_back(value);
    }
    return remember(value, table_[slot]);
  }
  const std::vector<T>& values() const { return values_; }

 private:
  static_assert(sizeof(T) % sizeof(std::uint32_t) == 0, "hashed as 32-bit words");
  static constexpr std::uint32_t kEmpty = ~0u;
  struct Recent {
    T value;
    std::uint32_t index;
  };
  static bool same(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }
  static std::uint64_t hash(const T& value) {
    std::uint32_t words[sizeof(T) / sizeof(std::uint32_t)];
    std::memcpy(words, &value, sizeof(T));
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const std::uint32_t w : words) h = (h ^ w) * 0xFF51AFD7ED558CCDull;  // bits, so -0 and 0 stay apart
    return h ^ (h >> 29);
  }
  std::size_t slotOf(const T& value) const {
    std::size_t slot = hash(value) & (table_.size() - 1);
    while (table_[slot] != kEmpty && !same(values_[table_[slot]], value)) slot = (slot + 1) & (table_.size() - 1);
    return slot;
  }
  std::uint32_t remember(const T& value, std::uint32_t index) {
    recent_[added_++ % 4] = Recent{value, index};
    return index;
  }
  std::vector<T> values_;
  std::vector<std::uint32_t> table_ = std::vector<std::uint32_t>(64, kEmpty);  // a power of two, at most half full
  std::array<Recent, 4> recent_{};
  std::size_t added_ = 0;
};

ObjPart barkPart(const QuadMesh& mesh, bool triangles, Up up, const std::string& mtlFile) {
  exporting::requirePerVertex(mesh, mesh.normals.size(), "normals", "writeObj");
  exporting::requirePerVertex(mesh, mesh.uvw.size(), "uvw", "writeObj");
  exporting::requireQuadIndicesInRange(mesh, "writeObj");
  const auto triangleList = std::make_shared<const std::vector<Triangle>>(triangles ? triangulate(mesh) : std::vector<Triangle>{});
  const std::size_t faceCount = triangles ? triangleList->size() : mesh.quads.size();
  ObjPart part;
  part.preamble = std::string("# Arbor tree mesh: object space in metres, ") + (up == Up::Y ? "y up" : "z up") + "\n# " +
                  std::to_string(mesh.vertexCount()) + " vertices, " + std::to_string(faceCount) + (triangles ? " triangles" : " quads") +
                  "; vt is (u, v), the flip coordinate is not stored\n";
  if (!mtlFile.empty()) part.preamble += "mtllib " + mtlFile + "\nusemtl bark\n";
  for (int section = 0; section < 3; ++section) part.count[section] = mesh.vertexCount();
  part.count[3] = faceCount;
  const QuadMesh* m = &mesh;  // the caller's mesh outlives the writing
  part.print[0] = eachLine([m, up](char*& out, std::size_t i) { appendAxes(out, "v", m->positions[i], up); });
  part.print[1] = eachLine([m](char*& out, std::size_t i) { appendLine(out, "vt", {m->uvw[i].x, m->uvw[i].y}); });
  part.print[2] = eachLine([m, up](char*& out, std::size_t i) { appendAxes(out, "vn", m->normals[i], up); });
  part.print[3] = eachLine([m, triangles, triangleList](char*& out, std::size_t i) {
    if (triangles) appendFace(out, (*triangleList)[i]);
    else appendFace(out, m->quads[i]);
  });
  return part;
}

// Cards' numbering: each distinct vt and vn once, and per card corner which.
struct CardNumbers {
  Distinct<glm::vec2> texcoords;
  Distinct<glm::vec3> normals;
  std::vector<std::array<std::uint32_t, 4>> vt;  // per card corner
  std::vector<std::uint32_t> vn;                 // per card: its corners share it
};
// The cards' v, vt and vn lines: all that does not depend on what precedes the cards in the file.
struct CardLines {
  std::size_t count[3] = {0, 0, 0};  // v, vt, vn
  std::shared_ptr<const CardNumbers> numbers;
  LinePrinter print[3];
};

// The lines of cards, `count` of them, card(i) making card i (once while numbering, again as printed).
CardLines cardLines(std::size_t count, std::function<Card(std::size_t)> card, Up up) {
  auto n = std::make_shared<CardNumbers>();
  n->vt.resize(count);
  n->vn.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Card c = card(i);
    // OBJ's v grows up the image, glTF's (and the cards') down it.
    for (std::size_t k = 0; k < 4; ++k) n->vt[i][k] = n->texcoords.add(glm::vec2(c.texcoords[k].x, 1.0f - c.texcoords[k].y));
    n->vn[i] = n->normals.add(c.normal);
  }
  CardLines lines;
  lines.count[0] = 4 * count;
  lines.count[1] = n->texcoords.values().size();
  lines.count[2] = n->normals.values().size();
  lines.numbers = n;
  lines.print[0] = [card, up](char*& out, std::size_t begin, std::size_t end) {
    Card c{};
    for (std::size_t i = begin; i < end; ++i) {
      if (i == begin || i % 4 == 0) c = card(i / 4);
      appendAxes(out, "v", c.corners[i % 4], up);
    }
  };
  lines.print[1] = eachLine([n](char*& out, std::size_t i) { appendLine(out, "vt", {n->texcoords.values()[i].x, n->texcoords.values()[i].y}); });
  lines.print[2] = eachLine([n, up](char*& out, std::size_t i) { appendAxes(out, "vn", n->normals.values()[i], up); });
  return lines;
}

// The cards as a part of the file, numbered after `before`, which then counts their lines too; sections in
// `printed` were printed ahead.
ObjPart cardsPart(const CardLines& lines, const std::string& object, const std::string& material, ObjCounts& before,
                  const std::array<std::vector<PrintedText>, 3>* printed = nullptr, const std::array<std::size_t, 3>& printedLines = {}) {
  ObjPart part;
  part.preamble = "o " + object + "\n" + (material.empty() ? std::string() : "usemtl " + material + "\n");
  for (int section = 0; section < 3; ++section) {
    part.count[section] = lines.count[section];
    part.print[section] = lines.print[section];
    part.printed[section] = printed ? &(*printed)[static_cast<std::size_t>(section)] : nullptr;
    part.printedLines[section] = printedLines[static_cast<std::size_t>(section)];
  }
  part.count[3] = lines.numbers->vn.size();
  const ObjCounts at = before;
  part.print[3] = eachLine([n = lines.numbers, at](char*& out, std::size_t i) {
    *out++ = 'f';
    for (std::size_t k = 0; k < 4; ++k) appendCorner(out, at.v + 4 * i + k, at.vt + n->vt[i][k], at.vn + n->vn[i]);
    *out++ = '\n';
  });
  before.v += part.count[0];
  before.vt += part.count[1];
  before.vn += part.count[2];
  return part;
}

ObjPart cardsPart(std::size_t count, std::function<Card(std::size_t)> card, const std::string& object, const std::string& material,
                  ObjCounts& before, Up up) {
  return cardsPart(cardLines(count, std::move(card), up), object, material, before);
}

// A CardMesh's cards as they stand: quad i has corners 4i to 4i + 3, all with one normal (leafCards and
// branchCards make them so).
ObjPart cardsPart(const CardMesh& cards, const std::string& object, const std::string& material, ObjCounts& before, Up up) {
  exporting::requireQuadIndicesInRange(cards.quads, cards.positions.size(), "writeObjCards");
  bool own = cards.positions.size() == 4 * cards.quads.size() && cards.normals.size() == cards.positions.size() &&
             cards.texcoords.size() == cards.positions.size();
  for (std::size_t i = 0; own && i < cards.quads.size(); ++i) {
    for (std::uint32_t k = 0; k < 4; ++k) {
      own = own && cards.quads[i][k] == 4 * i + k && std::memcmp(&cards.normals[4 * i + k], &cards.normals[4 * i], sizeof(glm::vec3)) == 0;
    }
  }
  if (!own) throw std::invalid_argument("writeObjCards: each card needs four corners of its own (quad i: 4i to 4i + 3) with one normal");
  const CardMesh* m = &cards;  // the caller's cards outlive the writing
  return cardsPart(
      cards.quads.size(),
      [m](std::size_t i) {
        const std::array<std::uint32_t, 4>& q = m->quads[i];
        return Card{{m->positions[q[0]], m->positions[q[1]], m->positions[q[2]], m->positions[q[3]]},
                    {m->texcoords[q[0]], m->texcoords[q[1]], m->texcoords[q[2]], m->texcoords[q[3]]},
                    m->normals[q[0]],
                    glm::vec3(0.0f)};
      },
      object, material, before, up);
}

}  // namespace

void writeObj(const QuadMesh& mesh, bool triangles, std::ostream& stream, Up up) { writeObj(mesh, triangles, stream, up, {}); }

void writeObj(const QuadMesh& mesh, bool triangles, std::ostream& stream, Up up, const std::string& mtlFile) {
  writeParts({barkPart(mesh, triangles, up, mtlFile)}, stream);
}

std::string writeObj(const QuadMesh& mesh, bool triangles, Up up) {
  std::ostringstream out;
  writeObj(mesh, triangles, out, up);
  return std::move(out).str();
}

void writeObjCards(const CardMesh& cards, const std::string& object, const std::string& material, ObjCounts& before, std::ostream& stream,
                   Up up) {
  writeParts({cardsPart(cards, object, material, before, up)}, stream);
}

struct ObjLeafLines {
  CardLines lines;
  std::array<std::vector<PrintedText>, 3> printed;  // v, vt, vn: blocks of each section's first lines
  std::array<std::size_t, 3> printedLines{};
  Up up = Up::Y;
};

std::shared_ptr<const ObjLeafLines> printObjLeafLines(const std::vector<Leaf>& leaves, Up up, const std::function<bool()>& enough) {
  auto ahead = std::make_shared<ObjLeafLines>();
  ahead->up = up;
  ahead->lines = cardLines(leaves.size(), [l = &leaves](std::size_t i) { return leafCard((*l)[i]); }, up);
  // The numbering is needed whatever; the lines only while the caller has other work (the writer prints the rest on
  // every core).
  for (std::size_t section = 0; section < 3; ++section) {
    const std::size_t count = ahead->lines.count[section];
    for (std::size_t& at = ahead->printedLines[section]; at < count && !enough();) {
      const std::size_t end = std::min(count, at + kBlockLines[0]);
      printBlock(ahead->lines.print[section], at, end, ahead->printed[section].emplace_back());
      at = end;
    }
  }
  return ahead;
}

namespace {

// The asset's parts: bark, then the fake branches' cards, then the leaves' (from `leaves`, or printed ahead).
void writeAssetParts(const QuadMesh& bark, const std::vector<ImpostorSegment>& branchSegments, const std::vector<Leaf>& leaves,
                     const ObjLeafLines* ahead, bool triangles, std::ostream& stream, Up up, const std::string& mtlFile) {
  std::vector<ObjPart> parts;
  parts.push_back(barkPart(bark, triangles, up, mtlFile));
  ObjCounts counts{bark.vertexCount(), bark.vertexCount(), bark.vertexCount()};
  const bool materials = !mtlFile.empty();
  // Two cards per segment that has them, made as they are printed (the willow's were 19 MB).
  const auto carded = std::make_shared<std::vector<const ImpostorSegment*>>();
  for (const ImpostorSegment& s : branchSegments)
    if (hasCards(s)) carded->push_back(&s);
  if (!carded->empty()) {
    parts.push_back(cardsPart(2 * carded->size(), [carded](std::size_t i) { return (*segmentCards(*(*carded)[i / 2]))[i % 2]; }, "branch_cards",
                              materials ? "branch_cards" : "", counts, up));
  }
  // One card per leaf, made as it is printed (the willow's 250,000 were 52 MB).
  const std::vector<Leaf>* l = &leaves;  // the caller's leaves outlive the writing
  if (ahead && ahead->lines.numbers->vn.size() > 0) {
    parts.push_back(cardsPart(ahead->lines, "leaves", materials ? "leaves" : "", counts, &ahead->printed, ahead->printedLines));
  } else if (!ahead && !leaves.empty()) {
    parts.push_back(cardsPart(leaves.size(), [l](std::size_t i) { return leafCard((*l)[i]); }, "leaves", materials ? "leaves" : "", counts, up));
  }
  writeParts(parts, stream);
}

}  // namespace

void writeObjAsset(const QuadMesh& bark, const std::vector<ImpostorSegment>& branchSegments, const std::vector<Leaf>& leaves, bool triangles,
                   std::ostream& stream, Up up, const std::string& mtlFile) {
  writeAssetParts(bark, branchSegments, leaves, nullptr, triangles, stream, up, mtlFile);
}

void writeObjAsset(const QuadMesh& bark, const std::vector<ImpostorSegment>& branchSegments, const ObjLeafLines& leaves, bool triangles,
                   std::ostream& stream, Up up, const std::string& mtlFile) {
  if (leaves.up != up) throw std::invalid_argument("writeObjAsset: the leaves' lines were printed for the other up axis");
  writeAssetParts(bark, branchSegments, {}, &leaves, triangles, stream, up, mtlFile);
}

std::string writeMtl(const std::string& barkColor, const std::string& barkNormal, const std::string& leafAtlas) {
  std::string out = "# Arbor tree materials\n";
  for (const char* bark : {"bark", "branch_cards"}) {
    out += std::string("\nnewmtl ") + bark + "\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nillum 1\n";
    out += "map_Kd " + barkColor + "\nmap_Bump -bm 1 " + barkNormal + "\n";
  }
  out += "\nnewmtl leaves\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nillum 1\nmap_Kd " + leafAtlas + "\nmap_d " + leafAtlas + "\n";
  return out;
}

QuadMesh readObj(const std::string& text, const std::string& file) {
  QuadMesh mesh;
  Reader reader{file};
  std::vector<std::size_t> faceLines;  // for naming a face whose index turns out too large
  std::optional<Triangle> pending;     // first triangle of a pair, waiting for its partner
  std::size_t pendingLine = 0;
  bool yUp = false;  // Arbor's own header says so; any other file is read as it stands

  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t stop = std::min(text.find('\n', start), text.size());
    ++reader.line;
    const auto w = words(std::string_view(text).substr(start, stop - start));
    start = stop + 1;
    if (reader.line == 1 && text.compare(0, 17, "# Arbor tree mesh") == 0) yUp = text.substr(0, stop).find("y up") != std::string::npos;
    if (w.empty() || w[0].front() == '#') continue;

    const std::string_view keyword = w[0];
    const std::size_t arguments = w.size() - 1;
    // Cards (leaves, fake branches) follow the tree's surface as objects of their own.
    if (keyword == "o" && arguments == 1 && isObjCardObject(w[1])) break;
    if (keyword == "v" || keyword == "vn") {
      if (arguments != 3) reader.fail(std::string(keyword) + " needs 3 numbers, found " + std::to_string(arguments));
      glm::vec3 value(reader.number(w[1]), reader.number(w[2]), reader.number(w[3]));
      if (yUp) value = glm::vec3(value.x, -value.z, value.y);
      (keyword == "v" ? mesh.positions : mesh.normals).push_back(value);
    } else if (keyword == "vt") {
      if (arguments != 2 && arguments != 3) reader.fail("vt needs 2 numbers, found " + std::to_string(arguments));
      mesh.uvw.emplace_back(reader.number(w[1]), reader.number(w[2]), 0.0f);
    } else if (keyword == "f") {
      if (arguments == 4) {
        if (pending) {
          reader.line = pendingLine;
          reader.fail("triangle has no partner to form a quad with");
        }
        mesh.quads.push_back({reader.corner(w[1]), reader.corner(w[2]), reader.corner(w[3]), reader.corner(w[4])});
        faceLines.push_back(reader.line);
      } else if (arguments == 3) {
        const Triangle t{reader.corner(w[1]), reader.corner(w[2]), reader.corner(w[3])};
        if (!pending) {
          pending = t;
          pendingLine = reader.line;
          continue;
        }
        const auto quad = joinTriangles(*pending, t);
        if (!quad) reader.fail("triangle does not share an edge with the triangle on line " + std::to_string(pendingLine));
        mesh.quads.push_back(*quad);
        faceLines.push_back(reader.line);
        pending.reset();
      } else {
        reader.fail("faces must have 3 or 4 corners, found " + std::to_string(arguments));
      }
    } else if (keyword != "o" && keyword != "g" && keyword != "s" && keyword != "mtllib" && keyword != "usemtl") {
      reader.fail("unsupported statement '" + std::string(keyword) + "'");
    }
  }
  if (pending) {
    reader.line = pendingLine;
    reader.fail("triangle has no partner to form a quad with");
  }

  const std::size_t count = mesh.positions.size();
  if (mesh.uvw.size() != count || mesh.normals.size() != count) {
    throw std::runtime_error(file + ": " + std::to_string(count) + " v, " + std::to_string(mesh.uvw.size()) + " vt and " +
                             std::to_string(mesh.normals.size()) + " vn lines; Arbor's OBJ has one of each per vertex");
  }
  for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
    for (const std::uint32_t v : mesh.quads[f]) {
      if (v >= count) {
        reader.line = faceLines[f];
        reader.fail("face refers to vertex " + std::to_string(std::uint64_t{v} + 1) + " but there are only " +
                    std::to_string(count));
      }
    }
  }
  return mesh;
}

}  // namespace arbor
