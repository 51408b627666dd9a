#version 450
#extension GL_GOOGLE_include_directive : require
// Ceiling (arbor bench tess): the ACC patches with nothing but their four corners and a uniform factor, so the
// benchmark can say what share of the device's bare tessellation rate each real mode reaches.

layout(vertices = 4) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) out vec3 corner[];

const uint kCornerPoint[4] = uint[4](0u, 3u, 15u, 12u);  // the Bezier corners, counter-clockwise

void main() {
  corner[gl_InvocationID] = control[entry[0].x * uint(ARBOR_ACC_CONTROL_VEC4S) + kCornerPoint[gl_InvocationID]].xyz;
  if (gl_InvocationID == 0) {
    float level = scene.tess.x;
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = level;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = level;
  }
}
