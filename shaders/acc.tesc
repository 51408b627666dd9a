#version 450
#extension GL_GOOGLE_include_directive : require
// ACC control stage: the patch's control points were built once per mesh (acc_control.comp) and its factors
// this frame (patch_cull.comp). Each invocation copies one Bezier point to the evaluation stage (its inputs are
// far cheaper to read there than the buffer, once per tessellated vertex), and the first sets the factors.

layout(vertices = 16) out;

#include "scene.glsl"

layout(location = 0) in uvec2 entry[];
layout(location = 0) out vec3 bezierPosition[];
layout(location = 1) out vec4 bezierUvwRadius[];       // u, v, w and radius follow the same construction
layout(location = 2) patch out vec3 cornerNormal[4];   // exact Catmull-Clark limit normals at the corners
layout(location = 6) patch out vec3 cornerUvw[4];      // corner texture coordinates, for the seam-safe mix
layout(location = 10) patch out uint patchIndex;

void main() {
  uint id = uint(gl_InvocationID);  // per-vertex outputs may only be written at [gl_InvocationID]
  uint base = entry[0].x * uint(ARBOR_ACC_CONTROL_VEC4S);
  vec4 point = control[base + id];
  bezierPosition[gl_InvocationID] = point.xyz;
  bezierUvwRadius[gl_InvocationID] = vec4(control[base + 16u + id].xyz, point.w);
  if (id < 4u) {
    cornerNormal[id] = control[base + 32u + id].xyz;
    cornerUvw[id] = control[base + 36u + id].xyz;
  }
  if (id == 0u) {
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
}
