#version 450
#extension GL_GOOGLE_include_directive : require
// PN triangles whose every factor is 1, drawn without the tessellator: the triangle through its corners with
// the corner normals, as pn.tese gives it at factor 1. Three vertices per triangle.

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

void main() {
  uint triangle = visible[uint(gl_VertexIndex) / 3u].x;
  uint corner = uint(gl_VertexIndex) % 3u;
  uint base = triangle * uint(ARBOR_PN_CONTROL_VEC4S);
  vec4 point = control[base + corner];
  vec3 p = point.xyz;
  vec3 n = normalize(control[base + 10u + corner].xyz);
  uvw = control[base + 16u + corner].xyz;
  radius = point.w;
  if (kDisplaced) p += n * displacement(uvw, radius, displacementLod(p, radius));
  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * n;
  gl_Position = scene.viewProj * world;
}
