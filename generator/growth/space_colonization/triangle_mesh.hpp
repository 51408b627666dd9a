#pragma once
// A closed triangle mesh read from an OBJ file: the obstacle an artist imports (Patrick et al.'s bike stations).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "growth/math.hpp"

namespace arbor::sc {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Vec3 low{0.0}, high{0.0};  // bounding box
};

// `v x y z` and `f a b c ...` lines (a/b/c forms, negative indices; polygons split into fans); everything else
// ignored. Throws InputError(file, field, ...) on bad numbers or indices, no triangle, or a mesh that is not
// closed (an edge not shared by exactly two triangles), so the inside test below means something.
TriangleMesh readObjMesh(const std::string& text, const std::string& file, const std::string& field);

// Ray parity: whether p is inside the closed mesh.
bool insideMesh(const TriangleMesh& mesh, const Vec3& p);

// Whether the segment a-b crosses a triangle of the mesh or has an end inside it.
bool segmentHitsMesh(const TriangleMesh& mesh, const Vec3& a, const Vec3& b);

}  // namespace arbor::sc
