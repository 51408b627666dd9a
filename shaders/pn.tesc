#version 450
#extension GL_GOOGLE_include_directive : require
// PN control stage: the triangle's cubic and quadratic points were built once per mesh (pn_control.comp) and
// its factors this frame (patch_cull.comp); copied here to the evaluation stage, whose inputs are far cheaper
// to read than the buffer once per tessellated vertex.

layout(vertices = 3) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) out vec3 cornerPosition[];
layout(location = 1) out vec3 cornerNormal[];
layout(location = 2) out vec4 cornerUvwRadius[];
// b210 b120 b021 b012 b102 b201 b111, and n110 n011 n101
layout(location = 3) patch out vec3 cubic[7];
layout(location = 10) patch out vec3 quadratic[3];

void main() {
  uint id = uint(gl_InvocationID);
  uint base = entry[0].x * uint(ARBOR_PN_CONTROL_VEC4S);
  vec4 corner = control[base + id];
  cornerPosition[gl_InvocationID] = corner.xyz;
  cornerNormal[gl_InvocationID] = control[base + 10u + id].xyz;
  cornerUvwRadius[gl_InvocationID] = vec4(control[base + 16u + id].xyz, corner.w);
  if (id == 0u) {
    for (uint i = 0u; i < 7u; ++i) cubic[i] = control[base + 3u + i].xyz;
    for (uint i = 0u; i < 3u; ++i) quadratic[i] = control[base + 13u + i].xyz;
    uint packed = entry[0].y;
    // Outer level i is the edge opposite corner i.
    float l0 = float(packed & 0xffu), l1 = float((packed >> 8) & 0xffu), l2 = float((packed >> 16) & 0xffu);
    gl_TessLevelOuter[0] = l0;
    gl_TessLevelOuter[1] = l1;
    gl_TessLevelOuter[2] = l2;
    gl_TessLevelInner[0] = max(l0, max(l1, l2));
  }
}
