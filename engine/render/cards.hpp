#pragma once
// Leaves and fake branches are cards (shaders/card.glsl): four vertices each, expanded by the vertex stage
// from gl_VertexIndex alone and drawn as indexed triangles, so no geometry stage is needed (on the H200 the
// 200-tree forest's trees took 15.7 ms with geometry shaders, 11.3 ms as cards: docs/PERFORMANCE.md).

#include <cstdint>
#include <vector>

namespace arbor::render {

// Cards one draw takes: the shared index buffer holds this many; longer runs are split into more draws.
constexpr std::uint32_t kCardsPerDraw = 65536;

// Six indices per card, slots (0, 1, 3) and (0, 3, 2) of its four vertices: both triangles start at slot 0.
std::vector<std::uint32_t> cardIndices(std::uint32_t cards);

}  // namespace arbor::render
