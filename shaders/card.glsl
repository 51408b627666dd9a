// Leaves and fake branches are cards: four vertices each, drawn as indexed triangles from one shared index
// buffer (render/cards.hpp) with nothing but gl_VertexIndex as input. gl_VertexIndex / 4 is the card and
// gl_VertexIndex % 4 its slot; both triangles, slots (0, 1, 3) and (0, 3, 2), begin at slot 0, the provoking
// vertex, so a flat output is needed there alone.

uint cardIndex() { return uint(gl_VertexIndex) >> 2; }
bool cardProvoking() { return (uint(gl_VertexIndex) & 3u) == 0u; }

// The slot's corner, bit 0 across the card and bit 1 along it: the triangles share the diagonal from corner 1
// to corner 2, as a strip of the corners in order would, which decides how values spread over a tapering card.
uint cardCorner() {
  const uint kCornerOfSlot[4] = uint[4](1u, 3u, 0u, 2u);
  return kCornerOfSlot[uint(gl_VertexIndex) & 3u];
}

// For a card this view leaves out: every corner at one point outside the clip volume draws nothing.
const vec4 kNoCard = vec4(2.0, 2.0, 2.0, 1.0);
