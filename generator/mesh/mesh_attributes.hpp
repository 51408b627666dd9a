#pragma once
#include "quad_mesh.hpp"

namespace arbor {

// Vertex normals: the area-weighted sum of the normals of the quads around each vertex.
void computeNormals(QuadMesh& mesh);

}  // namespace arbor
