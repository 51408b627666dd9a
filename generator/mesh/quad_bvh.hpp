#pragma once
// A bounding-volume hierarchy over quads' boxes (median splits on the longest axis): which quads' boxes
// overlap a query box, in logarithmic time, for the self-intersection check of meshes of millions of quads.
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace arbor {

struct QuadBox {
  glm::vec3 lo{0.0f}, hi{0.0f};
  bool overlaps(const QuadBox& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
  }
};

struct QuadBvh {
  struct Node {
    QuadBox box;
    std::uint32_t first = 0;  // inner: index of the left child (the right one follows); leaf: into `items`
    std::uint32_t count = 0;  // 0 for inner nodes
  };
  std::vector<Node> nodes;           // nodes[0] is the root
  std::vector<std::uint32_t> items;  // quad indices, leaves' runs
  std::vector<QuadBox> itemBoxes;    // their boxes in the same order: a leaf's boxes lie together in memory
};

QuadBvh buildQuadBvh(const std::vector<QuadBox>& boxes);

// A pair of nodes whose quads are still to be paired (first == second: the pairs within one node).
using NodePair = std::pair<std::uint32_t, std::uint32_t>;

// The root's node pairs split into at least `count` independent tasks (fewer for a small tree), for threads.
std::vector<NodePair> splitOverlapTasks(const QuadBvh& bvh, std::size_t count);

namespace detail {

// One step of a traversal of node x of `a` against node y of `b` (two different nodes when a is b): leaves' items
// paired, or the larger inner node split onto `stack` (boxes shrink fastest that way).
template <class Visit>
void descendPair(const QuadBvh& a, const QuadBvh& b, std::uint32_t x, std::uint32_t y, std::vector<NodePair>& stack, Visit& visit) {
  const QuadBvh::Node& nx = a.nodes[x];
  const QuadBvh::Node& ny = b.nodes[y];
  if (!nx.box.overlaps(ny.box)) return;
  if (nx.count > 0 && ny.count > 0) {
    for (std::uint32_t i = nx.first; i < nx.first + nx.count; ++i)
      for (std::uint32_t j = ny.first; j < ny.first + ny.count; ++j)
        if (a.itemBoxes[i].overlaps(b.itemBoxes[j])) visit(a.items[i], b.items[j]);
    return;
  }
  const glm::vec3 ex = nx.box.hi - nx.box.lo, ey = ny.box.hi - ny.box.lo;
  if (ny.count > 0 || (nx.count == 0 && ex.x + ex.y + ex.z >= ey.x + ey.y + ey.z)) {
    stack.push_back({nx.first, y});
    stack.push_back({nx.first + 1, y});
  } else {
    stack.push_back({x, ny.first});
    stack.push_back({x, ny.first + 1});
  }
}

}  // namespace detail

// Calls visit(i, j) once for every two quads i != j under `task` whose boxes overlap (the tree against itself:
// each pair once, not twice as a query per quad would).
template <class Visit>
void forEachOverlappingPair(const QuadBvh& bvh, NodePair task, Visit&& visit) {
  std::vector<NodePair> stack{task};
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    if (x != y) {
      detail::descendPair(bvh, bvh, x, y, stack, visit);
      continue;
    }
    const QuadBvh::Node& n = bvh.nodes[x];
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
        for (std::uint32_t j = i + 1; j < n.first + n.count; ++j)
          if (bvh.itemBoxes[i].overlaps(bvh.itemBoxes[j])) visit(bvh.items[i], bvh.items[j]);
    } else {
      stack.push_back({n.first, n.first});
      stack.push_back({n.first + 1, n.first + 1});
      stack.push_back({n.first, n.first + 1});
    }
  }
}

// Calls visit(i, j) once for every quad i of `a` and quad j of `b` whose boxes overlap (two trees, one against the
// other: a mesh's part searched against the parts before it).
template <class Visit>
void forEachOverlappingPair(const QuadBvh& a, const QuadBvh& b, Visit&& visit) {
  if (a.nodes.empty() || b.nodes.empty()) return;
  std::vector<NodePair> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    detail::descendPair(a, b, x, y, stack, visit);
  }
}

// Calls visit(i) for every quad i whose box overlaps `query`.
template <class Visit>
void forEachOverlap(const QuadBvh& bvh, const QuadBox& query, Visit&& visit) {
  if (bvh.nodes.empty()) return;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const QuadBvh::Node& n = bvh.nodes[stack[--top]];
    if (!n.box.overlaps(query)) continue;
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
        if (bvh.itemBoxes[k].overlaps(query)) visit(bvh.items[k]);
    } else {
      stack[top++] = n.first;
      stack[top++] = n.first + 1;
    }
  }
}

}  // namespace arbor
