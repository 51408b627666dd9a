#pragma once
// The 3D turtle of ABOP 1.5 and 2.2: a state (position, heading H, left L, up U with H x L = U, width,
// colour) that modules move, turn and push; its trail becomes a BranchGraph (docs/lsystem-format.md).
#include <cstdint>
#include <string>
#include <vector>

#include "growth/graph/branch_graph.hpp"
#include "lsystem.hpp"

namespace arbor::lsys {

struct TurtleState {
  Vec3 position{0.0};
  Vec3 heading{0.0, 0.0, 1.0};  // H: up for trees (z up)
  Vec3 left{-1.0, 0.0, 0.0};    // L
  Vec3 up{0.0, -1.0, 0.0};      // U = H x L: a 2D grammar draws in the x-z plane, seen from -y
  double width = 0;             // <= 0: none given (the pipe model decides)
  int colour = 0;
  std::int32_t node = 0;        // the graph node the turtle last stood on (F grows from it)
};

// Rotations in the right-handed sense about one axis of the turtle's frame, angles in radians.
void turn(TurtleState& t, double angle);   // about U: H toward L ('+' turns left by delta)
void pitch(TurtleState& t, double angle);  // about L: H toward -U ('&' pitches down)
void roll(TurtleState& t, double angle);   // about H: L toward U ('/')
void turnAround(TurtleState& t);           // '|': H and L negated
void rollHorizontal(TurtleState& t, const Vec3& vertical);  // '$': L = V x H / |V x H|, U = H x L
// ABOP eq. 2.3: H rotated about H x T by e |H x T| (toward T for e > 0), L and U with it.
void bend(TurtleState& t, const Vec3& tropism, double susceptibility);

struct TurtleSettings {
  double step = 1;              // F and f without an argument
  double angle = 90;            // degrees, turns without an argument
  double widthFactor = 0.707;   // '!' without an argument multiplies the width by this
  Vec3 tropism{0.0};
  double susceptibility = 0;
  Vec3 vertical{0.0, 0.0, 1.0}; // V of '$'
  int leafKind = 0;
  TurtleState start;
  std::string file = "(l-system)";
};

TurtleSettings turtleSettings(const Lsystem& system);
// The same settings in the drawing plane of the SVG: H = +y, L = -x, U = +z, V = +y; the 3D tree's x-z plane
// seen from -y becomes the picture's x-y plane (T mapped with it).
TurtleSettings planarTurtleSettings(const Lsystem& system);

struct TurtleSegment {
  Vec3 from{0.0}, to{0.0};
  double width = 0;
  int colour = 0;
};

struct TurtlePolygon {
  std::vector<Vec3> vertices;
  int colour = 0;
};

struct Interpretation {
  BranchGraph graph;           // node 0 at the start position; one node per drawn F (an F over an earlier one's line: none)
  TurtleState last;            // the state after the last module
  std::size_t segments = 0;    // internodes drawn (a line drawn twice counts once)
  std::vector<TurtleSegment> drawing;   // only with recordDrawing
  std::vector<TurtlePolygon> polygons;  // only with recordDrawing
};

// Runs the turtle over a derived string. Throws InputError for a ']' without '['.
Interpretation interpret(const ModuleString& str, const TurtleSettings& settings, bool recordDrawing = false);

// A polygon's outline as a leaf: base at the first vertex, along the farthest vertex, width across it.
// False when the polygon has no area.
bool polygonLeaf(const std::vector<Vec3>& vertices, const Vec3& fallbackNormal, GraphLeaf& leaf);

}  // namespace arbor::lsys
