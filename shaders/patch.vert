#version 450
#extension GL_GOOGLE_include_directive : require
// Tessellated modes: one input vertex per patch, the culling pass's entry for it (patch index, packed factors);
// the draw's first vertex points into this frame's patch list.

#include "scene.glsl"

layout(location = 0) out uvec2 entry;

void main() {
  entry = visible[gl_VertexIndex];
  gl_Position = vec4(0.0);
}
