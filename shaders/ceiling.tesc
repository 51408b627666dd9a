#version 450
#extension GL_GOOGLE_include_directive : require
// Ceiling (arbor bench tess): the ACC patches with nothing but their four corners and a uniform factor, so the
// benchmark can say what share of the device's bare tessellation rate each real mode reaches.

layout(vertices = 1) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) patch out uint patchIndex;

void main() {
  patchIndex = entry[0].x;
  float level = scene.tess.x;
  gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = level;
  gl_TessLevelInner[0] = gl_TessLevelInner[1] = level;
}
