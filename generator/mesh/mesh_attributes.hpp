#pragma once
#include "quad_mesh.hpp"

namespace arbor {

// Vertex normals: the area-weighted sum of the normals of the quads around each vertex.
void computeNormals(QuadMesh& mesh);

// How far texture v advances over `distance` along a branch of `radius`: by the bark scale 0.2 + 0.8 r,
// normalised by pi (u spans half a turn), so bark keeps its aspect on thin and thick branches alike.
double barkTextureAdvance(double distance, double radius);

}  // namespace arbor
