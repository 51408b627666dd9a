#pragma once
// Shape checks every exporter runs first: a short array or a stray index would otherwise read past the end.
#include <stdexcept>
#include <string>

#include "mesh/quad_mesh.hpp"

namespace arbor::exporting {

// Throws std::invalid_argument when an attribute array the caller reads does not have one entry per vertex.
inline void requirePerVertex(const QuadMesh& mesh, std::size_t size, const char* attribute, const char* context) {
  if (size != mesh.vertexCount()) {
    throw std::invalid_argument(std::string(context) + ": mesh has " + std::to_string(mesh.vertexCount()) +
                                " positions but " + std::to_string(size) + " " + attribute);
  }
}

// Throws std::invalid_argument when a quad refers past the last of `vertices` vertices.
inline void requireQuadIndicesInRange(const std::vector<std::array<std::uint32_t, 4>>& quads, std::size_t vertices, const char* context) {
  for (std::size_t f = 0; f < quads.size(); ++f) {
    for (const std::uint32_t v : quads[f]) {
      if (v >= vertices) {
        throw std::invalid_argument(std::string(context) + ": quad " + std::to_string(f) + " refers to vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertices));
      }
    }
  }
}

inline void requireQuadIndicesInRange(const QuadMesh& mesh, const char* context) {
  requireQuadIndicesInRange(mesh.quads, mesh.vertexCount(), context);
}

}  // namespace arbor::exporting
