#version 450
#extension GL_GOOGLE_include_directive : require
// PN control stage: the triangle's cubic and quadratic points were built once per mesh (pn_control.comp) and
// its factors this frame (patch_cull.comp).

layout(vertices = 1) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) patch out uint triangle;

void main() {
  triangle = entry[0].x;
  uint packed = entry[0].y;
  // Outer level i is the edge opposite corner i.
  float l0 = float(packed & 0xffu), l1 = float((packed >> 8) & 0xffu), l2 = float((packed >> 16) & 0xffu);
  gl_TessLevelOuter[0] = l0;
  gl_TessLevelOuter[1] = l1;
  gl_TessLevelOuter[2] = l2;
  gl_TessLevelInner[0] = max(l0, max(l1, l2));
}
