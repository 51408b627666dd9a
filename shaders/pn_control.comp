#version 450
#extension GL_GOOGLE_include_directive : require
// Curved PN triangles (Vlachos et al. 2001), once per mesh: from each triangle's corners and vertex normals a
// cubic Bezier triangle for position and a quadratic one for normals, and the hull the culling pass tests.

#include "compute.glsl"

layout(local_size_x = ARBOR_COMPUTE_GROUP) in;

vec3 position[3];
vec3 normal[3];
vec3 b[10];  // b300 b030 b003 (the corners), b210 b120 b021 b012 b102 b201, b111

// Edge control point near i on the edge to j: the point a third along, projected onto i's tangent plane.
vec3 edgePoint(int i, int j) {
  vec3 pi = position[i], pj = position[j];
  return (2.0 * pi + pj - dot(pj - pi, normal[i]) * normal[i]) / 3.0;
}

vec3 edgeNormal(int i, int j) {
  vec3 d = position[j] - position[i];
  float vij = 2.0 * dot(d, normal[i] + normal[j]) / max(dot(d, d), 1e-20);
  return normalize(normal[i] + normal[j] - vij * d);
}

// The derivatives towards corner 1 (u) and corner 2 (v) are quadratic triangles whose points are these
// differences (b_(i,j+1,k) - b_(i+1,j,k) and b_(i,j,k+1) - b_(i+1,j,k), exponents of w, u, v), so the normal
// lies in the cone of their 36 cross products.
const int kDu[12] = int[12](3, 0, 4, 3, 1, 4, 9, 8, 5, 9, 6, 7);  // (to, from) pairs: b210 - b300, b120 - b210, ...
const int kDv[12] = int[12](8, 0, 9, 3, 5, 4, 7, 8, 6, 9, 2, 7);
const int kNormalCandidates = 36;
vec3 normalCandidate(int k) {
  int i = k / 6, j = k % 6;
  return cross(b[kDu[2 * i]] - b[kDu[2 * i + 1]], b[kDv[2 * j]] - b[kDv[2 * j + 1]]);
}

#include "normal_cone.glsl"

void main() {
  uint triangle = gl_GlobalInvocationID.x;
  if (triangle >= pass.primitiveCount) return;
  uint base = triangle * uint(ARBOR_PN_CONTROL_VEC4S);
  float radius = 0.0;
  for (int i = 0; i < 3; ++i) {
    TreeVertex v = vertices[triangleIndices[3u * triangle + uint(i)]];
    position[i] = v.positionRadius.xyz;
    normal[i] = normalize(v.normalLevel.xyz);
    control[base + uint(i)] = v.positionRadius;
    control[base + 10u + uint(i)] = vec4(normal[i], 0.0);
    control[base + 16u + uint(i)] = vec4(v.uvw.xyz, 0.0);
    radius = max(radius, v.positionRadius.w);
  }
  b[0] = position[0];
  b[1] = position[1];
  b[2] = position[2];
  b[3] = edgePoint(0, 1);  // b210
  b[4] = edgePoint(1, 0);  // b120
  b[5] = edgePoint(1, 2);  // b021
  b[6] = edgePoint(2, 1);  // b012
  b[7] = edgePoint(2, 0);  // b102
  b[8] = edgePoint(0, 2);  // b201
  vec3 e = (b[3] + b[4] + b[5] + b[6] + b[7] + b[8]) / 6.0;
  vec3 c = (position[0] + position[1] + position[2]) / 3.0;
  b[9] = e + (e - c) * 0.5;  // b111
  for (int i = 0; i < 7; ++i) control[base + 3u + uint(i)] = vec4(b[3 + i], 0.0);
  control[base + 13u] = vec4(edgeNormal(0, 1), 0.0);
  control[base + 14u] = vec4(edgeNormal(1, 2), 0.0);
  control[base + 15u] = vec4(edgeNormal(2, 0), 0.0);

  vec3 lo = b[0], hi = b[0];
  for (int i = 1; i < 10; ++i) {
    lo = min(lo, b[i]);
    hi = max(hi, b[i]);
  }
  hulls[3u * triangle] = vec4(lo, radius);
  hulls[3u * triangle + 1u] = vec4(hi, 0.0);
  hulls[3u * triangle + 2u] = normalCone();
}
