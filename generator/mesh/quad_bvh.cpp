#include "quad_bvh.hpp"

#include <algorithm>

namespace arbor {

namespace {

constexpr std::uint32_t kLeafSize = 4;  // quads per leaf: fewer nodes, still few box tests per leaf

QuadBox unite(const QuadBox& a, const QuadBox& b) { return QuadBox{glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; }

// Fills node `at` with items[begin, end), splitting at the median centre along the longest axis.
void buildNode(QuadBvh& bvh, const std::vector<QuadBox>& boxes, std::uint32_t at, std::uint32_t begin, std::uint32_t end) {
  QuadBox box = boxes[bvh.items[begin]];
  glm::vec3 cLo = box.lo + box.hi, cHi = cLo;  // centres, doubled
  for (std::uint32_t k = begin + 1; k < end; ++k) {
    const QuadBox& b = boxes[bvh.items[k]];
    box = unite(box, b);
    cLo = glm::min(cLo, b.lo + b.hi);
    cHi = glm::max(cHi, b.lo + b.hi);
  }
  bvh.nodes[at].box = box;
  if (end - begin <= kLeafSize) {
    bvh.nodes[at].first = begin;
    bvh.nodes[at].count = end - begin;
    return;
  }
  const glm::vec3 extent = cHi - cLo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(bvh.items.begin() + begin, bvh.items.begin() + mid, bvh.items.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     return boxes[a].lo[axis] + boxes[a].hi[axis] < boxes[b].lo[axis] + boxes[b].hi[axis];
                   });
  const auto left = static_cast<std::uint32_t>(bvh.nodes.size());
  bvh.nodes.resize(bvh.nodes.size() + 2);
  bvh.nodes[at].first = left;
  bvh.nodes[at].count = 0;
  buildNode(bvh, boxes, left, begin, mid);
  buildNode(bvh, boxes, left + 1, mid, end);
}

}  // namespace

QuadBvh buildQuadBvh(const std::vector<QuadBox>& boxes) {
  QuadBvh bvh;
  if (boxes.empty()) return bvh;
  bvh.items.resize(boxes.size());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) bvh.items[i] = i;
  bvh.nodes.reserve(2 * boxes.size() / kLeafSize + 1);
  bvh.nodes.resize(1);
  buildNode(bvh, boxes, 0, 0, static_cast<std::uint32_t>(boxes.size()));
  bvh.itemBoxes.resize(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) bvh.itemBoxes[k] = boxes[bvh.items[k]];
  return bvh;
}

std::vector<NodePair> splitOverlapTasks(const QuadBvh& bvh, std::size_t count) {
  if (bvh.nodes.empty()) return {};
  std::vector<NodePair> tasks{{0, 0}};
  // Breadth first: each round replaces every task over an inner node by the tasks of its children.
  for (bool grew = true; grew && tasks.size() < count;) {
    grew = false;
    std::vector<NodePair> next;
    for (const NodePair& t : tasks) {
      const QuadBvh::Node& nx = bvh.nodes[t.first];
      const QuadBvh::Node& ny = bvh.nodes[t.second];
      if (t.first == t.second && nx.count == 0) {
        next.push_back({nx.first, nx.first});
        next.push_back({nx.first + 1, nx.first + 1});
        next.push_back({nx.first, nx.first + 1});
        grew = true;
      } else if (t.first != t.second && nx.count == 0 && nx.box.overlaps(ny.box)) {
        next.push_back({nx.first, t.second});
        next.push_back({nx.first + 1, t.second});
        grew = true;
      } else if (t.first == t.second || nx.box.overlaps(ny.box)) {
        next.push_back(t);
      }
    }
    tasks = std::move(next);
  }
  return tasks;
}

}  // namespace arbor
