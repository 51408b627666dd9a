#version 450
#extension GL_GOOGLE_include_directive : require
// Ceiling (arbor bench tess): the ACC patches with nothing but their four corners and a uniform factor, so
// the benchmark can say what share of the device's bare tessellation rate each real mode reaches.

layout(vertices = 4) out;

#include "scene.glsl"

layout(location = 0) out vec3 corner[];

void main() {
  uvec4 record = patches[draw.patchBase + uint(gl_PrimitiveID)];
  corner[gl_InvocationID] = vertices[points[record.x + uint(gl_InvocationID)]].positionRadius.xyz;
  if (gl_InvocationID == 0) {
    float level = scene.tess.x;
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = level;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = level;
  }
}
