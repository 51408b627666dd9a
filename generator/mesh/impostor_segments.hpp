#pragma once
// Fake branches (Nystad 5.5.4): the stems the mesh leaves out, as one segment per skeleton edge, for the
// renderer to draw as view-oriented rectangles between each node and its parent, scaled by the radii.
#include <cstdint>
#include <vector>

#include "growth/skeleton.hpp"
#include "tree_mesh.hpp"

namespace arbor {

struct ImpostorSegment {
  Vec3 from{}, to{};                   // object space: the parent node, the node
  double fromRadius = 0, toRadius = 0; // the edge's radius leaving the parent node, arriving at the node
  double fromV = 0, toV = 0;           // bark texture v along the stem (continuing from the stem's start)
  int level = 0;
  std::int32_t fromNode = -1, toNode = -1;  // the skeleton nodes at the ends (what moves them in the wind)
};

// Segments of every stem of `fromLevel` and deeper, in node order (parents before children).
std::vector<ImpostorSegment> impostorSegments(const Skeleton& skeleton, int fromLevel);

// Segments of the listed stems only, each from its attach node (the children TreeMesh::fakedStems lists).
std::vector<ImpostorSegment> stemSegments(const Skeleton& skeleton, const std::vector<int>& stems);

// Every stem the mesh left out: those of `fromLevel` and deeper (stubs at any level), then the listed faked stems.
std::vector<ImpostorSegment> leftOutSegments(const Skeleton& skeleton, int fromLevel, const std::vector<int>& fakedStems);

// A sketch of the stems of levels [fromLevel, belowLevel) for trees far away: one segment per stem segment,
// joint to joint (the nodes around branch points left out): the tupelo's is a quarter of impostorSegments'.
std::vector<ImpostorSegment> sketchSegments(const Skeleton& skeleton, int fromLevel, int belowLevel);

}  // namespace arbor
