#pragma once
// Wavefront OBJ for artists' tools: the quad mesh as it is, object space in metres, y up as Blender, Maya and
// most engines import OBJ (z up on request, the project's own axes).
// One vertex carries one position, one texture coordinate and one normal, so every face corner is "i/i/i".
#include <ostream>
#include <string>

#include "mesh/quad_mesh.hpp"

namespace arbor {

// `v x y z`, `vt u v` (the flip coordinate w has no place in OBJ), `vn x y z`, then one `f` per quad,
// or two per quad split by arbor::triangulate when `triangles` is set. Numbers are written in the
// shortest form that reads back as the same float. Needs positions, uvw and normals for every vertex;
// throws std::invalid_argument otherwise.
// Up::Y turns the tree (z up inside Arbor) to y up: (x, y, z) -> (x, z, -y), a rotation, so windings and
// normals stay outward; the header says which.
enum class Up { Y, Z };
std::string writeObj(const QuadMesh& mesh, bool triangles, Up up = Up::Y);
// The same, streamed a megabyte at a time (a tree's OBJ is tens of megabytes).
void writeObj(const QuadMesh& mesh, bool triangles, std::ostream& out, Up up = Up::Y);

// Reads what writeObj writes: v, vt, vn and f lines with 1-based "a/a/a" corners; comments, o, g, s,
// mtllib and usemtl are skipped. Triangles must come in the consecutive pairs writeObj emits, and each
// pair is joined back into its quad (QuadMesh holds quads only). The result has positions, normals,
// uvw (w = 0) and quads; tangents, radius, level and openBoundary are not in OBJ and stay empty. A file
// whose Arbor header says "y up" is turned back to z up.
// Throws std::runtime_error naming `file` and the line on anything else.
QuadMesh readObj(const std::string& text, const std::string& file);

}  // namespace arbor
