#pragma once
// Wind (docs/wind.md): the trunk bends with the wind's push and its gusts, each branch level sways about that
// with its own period and every stem with its own phase, leaves flutter. A point's motion is a function of its
// rest position and a WindPoint (how far along each ancestor stem it sits), so points the mesh shares move
// alike: applied to the control cage, the refined surface stays crack-free. The same function moves the
// renderer's cage (shaders/wind.glsl) and the exported animation.
#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "growth/skeleton.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/tree_mesh.hpp"

namespace arbor {

struct WindSettings {
  double azimuth = 0.0;         // degrees: where the wind blows towards, from +x counter-clockwise
  double strength = 0.0;        // 0: still; 1: a strong breeze (the trunk's top bends about 4 % of the height)
  double gustFrequency = 0.25;  // Hz: gusts; every motion repeats after 1 / gustFrequency seconds
  bool on() const { return strength > 0.0; }
  double period() const { return 1.0 / gustFrequency; }
};

// Per point: for branch levels 1, 2 and 3+ of the stems it hangs from, its reach on that stem (metres: a^2 / L
// for a point a metres along a stem L long, a beam's bending shape; 0 at the stem's base, so a child's base
// moves exactly with its parent) and that stem's phase (radians, from the stem's key).
struct WindPoint {
  std::array<float, 3> reach{};
  std::array<float, 3> phase{};
};

// The point `arc` metres along stem `stem` (its own and its ancestors' reaches).
WindPoint stemWindPoint(const Skeleton& skeleton, int stem, double arc);
// At a skeleton node.
WindPoint nodeWindPoint(const Skeleton& skeleton, int node);
// Per mesh vertex: on the stem of its lowest-level quad (shared joint vertices move with the parent), at its
// projection on that stem's skeleton.
std::vector<WindPoint> meshWindPoints(const Skeleton& skeleton, const TreeMesh& mesh);
// Per leaf: at the node it hangs from.
std::vector<WindPoint> leafWindPoints(const Skeleton& skeleton);

// The tree's height (for the trunk's bend): the highest node above the base.
double windHeight(const Skeleton& skeleton);
// The tree's own phase in the gusts (radians, from its species and seed), so that a forest's trees do not all
// bend at once.
double windPhase(const Skeleton& skeleton);

// How far `rest` moves at time `seconds` on a tree `treeHeight` high whose motion runs `treePhase` radians
// ahead in the gust period.
glm::vec3 windOffset(const glm::vec3& rest, const WindPoint& point, const WindSettings& wind, double treeHeight, double treePhase,
                     double seconds);

// A leaf's flutter: the tip's displacement along the blade's normal, in blade lengths, for leaf `index` (its
// phase: leafFlutterPhase).
double leafFlutter(const WindSettings& wind, std::uint32_t index, double seconds);
float leafFlutterPhase(std::uint32_t index);

// What the renderer needs to move a built tree: the points of its mesh vertices, leaves (skeleton order) and
// fake-branch segment ends (from, to for each segment of `impostors`, then of `sketch`), and its height.
struct TreeWind {
  double height = 0.0;
  double phase = 0.0;  // windPhase
  std::vector<WindPoint> mesh, leaves, segmentEnds;
  bool empty() const { return mesh.empty() && leaves.empty() && segmentEnds.empty(); }
};
TreeWind treeWind(const Skeleton& skeleton, const TreeMesh& mesh, const std::vector<ImpostorSegment>& impostors,
                  const std::vector<ImpostorSegment>& sketch);

}  // namespace arbor
