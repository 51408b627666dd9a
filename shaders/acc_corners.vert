#version 450
#extension GL_GOOGLE_include_directive : require
// ACC patches whose every factor is 1, drawn without the tessellator: the two triangles the tessellator makes
// at factor 1, through the patch's corners. At a corner evaluateAcc (acc_evaluate.glsl) reduces to the corner
// point, its two neighbours along the patch and the corner's limit normal; this is that arithmetic, in its
// order, reading 6 of the patch's 40 control vec4s. Six vertices per patch; gl_VertexIndex / 6 is its entry in
// this frame's list.

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

const uint kCorner[6] = uint[6](0u, 1u, 3u, 1u, 2u, 3u);  // the tessellator's split at factor 1 (lavapipe)
// Per corner: its Bezier point, and the two points evaluateAcc's derivative and geometry normal there use,
// in the order (a - b) of pu and pv.
const uint kPoint[4] = uint[4](0u, 3u, 15u, 12u);
const uvec2 kU[4] = uvec2[4](uvec2(1u, 0u), uvec2(3u, 2u), uvec2(15u, 14u), uvec2(13u, 12u));  // pu = 3 (x - y)
const uvec2 kV[4] = uvec2[4](uvec2(4u, 0u), uvec2(7u, 3u), uvec2(15u, 11u), uvec2(12u, 8u));   // pv = 3 (x - y)

vec3 safeNormalize(vec3 v) { return dot(v, v) > 1e-30 ? normalize(v) : vec3(0.0); }
vec3 at(uint base, uint i) { return control[base + i].xyz; }

void main() {
  uint base = visible[uint(gl_VertexIndex) / 6u].x * uint(ARBOR_ACC_CONTROL_VEC4S);
  uint corner = kCorner[uint(gl_VertexIndex) % 6u];
  vec4 point = control[base + kPoint[corner]];
  vec3 a = control[base + 16u + kPoint[corner]].xyz;
  vec3 limitNormal = control[base + 32u + corner].xyz;
  vec3 cageUvw = control[base + 36u + corner].xyz;
  vec3 u0 = at(base, kU[corner].x), u1 = at(base, kU[corner].y), v0 = at(base, kV[corner].x), v1 = at(base, kV[corner].y);

  vec3 n = safeNormalize(cross(3.0 * u0 - 3.0 * u1, 3.0 * v0 - 3.0 * v1));
  bool limitNormals = any(notEqual(control[base + 32u].xyz, vec3(0.0)));  // fallback patches have none
  if (limitNormals) n += limitNormal - safeNormalize(cross(u0 - u1, v0 - v1));
  n = safeNormalize(n);
  float flip = a.z;
  uvw = vec3(abs(flip) * a.x + (1.0 - abs(flip)) * cageUvw.x, a.y, flip);
  radius = point.w;
  vec3 p = point.xyz;
  if (kDisplaced) p += (limitNormals ? safeNormalize(limitNormal) : n) * displacement(uvw, radius, displacementLod(p, radius));
  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * n;
  gl_Position = scene.viewProj * world;
}
