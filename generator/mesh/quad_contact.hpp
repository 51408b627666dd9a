#pragma once
// Whether two quads of one mesh intersect, counting only where they meet beyond the corners they share:
// neighbours touch by construction, a fold or a neck through its own parent does not.
#include <array>
#include <cstdint>
#include <optional>

#include "growth/math.hpp"

namespace arbor {

// What two quads share: nothing, one corner (or two opposite ones), or an edge.
enum class QuadContact : std::uint8_t { Apart, Vertex, Edge };

// A quad's corners with their vertex indices (shared corners are recognised by index, not by position).
struct QuadCorners {
  std::array<Vec3, 4> p{};
  std::array<std::uint32_t, 4> index{};
};

QuadContact quadContact(const std::array<std::uint32_t, 4>& a, const std::array<std::uint32_t, 4>& b);

// Whether two quads share a corner (quadContact is not Apart), without branches: the searches ask it of millions
// of neighbouring pairs whose boxes overlap.
inline bool shareCorner(const std::array<std::uint32_t, 4>& a, const std::array<std::uint32_t, 4>& b) {
  unsigned shared = 0;
  for (const std::uint32_t x : a) shared |= static_cast<unsigned>(x == b[0]) | static_cast<unsigned>(x == b[1]) | static_cast<unsigned>(x == b[2]) | static_cast<unsigned>(x == b[3]);
  return shared != 0;
}

// A point where quads a and b meet other than at their shared corners and edge; nullopt when they do not.
// Each quad is split along its shorter diagonal, as the exports triangulate it. Contacts within a tolerance
// relative to the quads' size (and to float rounding of their coordinates) are touching, not intersecting.
std::optional<Vec3> quadsMeet(const QuadCorners& a, const QuadCorners& b);

}  // namespace arbor
