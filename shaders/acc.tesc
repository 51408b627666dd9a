#version 450
#extension GL_GOOGLE_include_directive : require
// ACC control stage: the patch's control points were built once per mesh (acc_control.comp) and its factors
// this frame (patch_cull.comp); all that is left is to hand them to the tessellator.

layout(vertices = 1) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) patch out uint patchIndex;

void main() {
  patchIndex = entry[0].x;
  uint packed = entry[0].y;
  // Outer levels: u = 0, v = 0, u = 1, v = 1; each inner level the finer of the two edges along it.
  float l0 = float(packed & 0xffu), l1 = float((packed >> 8) & 0xffu), l2 = float((packed >> 16) & 0xffu), l3 = float(packed >> 24);
  gl_TessLevelOuter[0] = l0;
  gl_TessLevelOuter[1] = l1;
  gl_TessLevelOuter[2] = l2;
  gl_TessLevelOuter[3] = l3;
  gl_TessLevelInner[0] = max(l1, l3);
  gl_TessLevelInner[1] = max(l0, l2);
}
