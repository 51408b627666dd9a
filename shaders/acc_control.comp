#version 450
#extension GL_GOOGLE_include_directive : require
// Loop & Schaefer's approximation of Catmull-Clark (ACC), once per mesh: from each quad and its 1-ring the 16
// points of a bicubic Bezier patch (positions, and u, v, w and radius by the same construction), the exact
// Catmull-Clark limit normals at its corners, and the hull the culling pass tests. Regular patches come out
// exactly as their B-spline. generator/patches/acc.cpp is the same construction in the same order (the
// tests' reference).

#include "compute.glsl"

layout(local_size_x = ARBOR_COMPUTE_GROUP) in;

uvec4 record;  // offset, valences, prefixes, kind

uint valenceOf(int corner) { return (record.y >> (8 * corner)) & 0xffu; }
uint prefixOf(int corner) { return (record.z >> (8 * corner)) & 0xffu; }
uint cornerVertex(int corner) { return points[record.x + uint(corner & 3)]; }

// The ring of a corner, counter-clockwise from the next corner: edge neighbours at even, diagonals at odd j.
uint ringVertex(int corner, uint j) {
  if (j < 3u) return cornerVertex(corner + 1 + int(j));
  uint count = 0u;
  for (int i = 0; i < 4; ++i) count += valenceOf(i);
  uint loopSize = 2u * count - 20u;  // 2 (n0 + n1 + n2 + n3) - 16 points minus the 4 corners
  return points[record.x + 4u + (prefixOf(corner) + j - 3u) % loopSize];
}

vec3 positionOf(uint v) { return vertices[v].positionRadius.xyz; }
vec4 attributeOf(uint v) { return vec4(vertices[v].uvw.xyz, vertices[v].positionRadius.w); }

// Interior point of face k about the corner: (n v + 2 e_k + 2 e_(k+1) + f_k) / (n + 5).
void interior(int corner, uint n, uint k, out vec3 p, out vec4 a) {
  uint v = cornerVertex(corner);
  uint e0 = ringVertex(corner, 2u * k), f = ringVertex(corner, 2u * k + 1u), e1 = ringVertex(corner, (2u * k + 2u) % (2u * n));
  float weight = 1.0 / (float(n) + 5.0);
  p = (float(n) * positionOf(v) + 2.0 * positionOf(e0) + 2.0 * positionOf(e1) + positionOf(f)) * weight;
  a = (float(n) * attributeOf(v) + 2.0 * attributeOf(e0) + 2.0 * attributeOf(e1) + attributeOf(f)) * weight;
}

// Catmull-Clark's limit normal at a corner, from its limit tangent masks.
vec3 limitNormal(int corner) {
  uint n = valenceOf(corner);
  float c1 = cos(2.0 * PI / float(n));
  float A = 1.0 + c1 + cos(PI / float(n)) * sqrt(2.0 * (9.0 + c1));
  vec3 t1 = vec3(0.0), t2 = vec3(0.0);
  for (uint k = 0u; k < n; ++k) {
    float ck = cos(2.0 * PI * float(k) / float(n));
    float cNext = cos(2.0 * PI * float(k + 1u) / float(n));
    float cPrev = cos(2.0 * PI * (float(k) - 1.0) / float(n));
    vec3 e = positionOf(ringVertex(corner, 2u * k)), f = positionOf(ringVertex(corner, 2u * k + 1u));
    t1 += A * ck * e + (ck + cNext) * f;
    t2 += A * cPrev * e + (cPrev + ck) * f;
  }
  return normalize(cross(t1, t2));
}

// Which corner owns each control point [row * 4 + column], and what it is there:
// 0 the corner (limit) point, 1 the edge point towards the next corner, 2 towards the previous, 3 interior.
const int kCorner[16] = int[16](0, 0, 1, 1, 0, 0, 1, 1, 3, 3, 2, 2, 3, 3, 2, 2);
const int kRole[16] = int[16](0, 1, 2, 0, 2, 3, 3, 1, 1, 3, 3, 2, 0, 2, 1, 0);

void controlPoint(int id, out vec3 p, out vec4 a) {
  int row = id / 4, column = id % 4;
  if (record.w == 2u) {
    // Fallback (open boundary): the bilinear quad through the corners.
    vec2 t = vec2(float(column), float(row)) / 3.0;
    uint c0 = cornerVertex(0), c1 = cornerVertex(1), c2 = cornerVertex(2), c3 = cornerVertex(3);
    p = mix(mix(positionOf(c0), positionOf(c1), t.x), mix(positionOf(c3), positionOf(c2), t.x), t.y);
    a = mix(mix(attributeOf(c0), attributeOf(c1), t.x), mix(attributeOf(c3), attributeOf(c2), t.x), t.y);
    return;
  }
  int corner = kCorner[id], role = kRole[id];
  uint n = valenceOf(corner);
  if (role == 3) {
    interior(corner, n, 0u, p, a);
  } else if (role == 0) {
    p = vec3(0.0);
    a = vec4(0.0);
    for (uint k = 0u; k < n; ++k) {
      vec3 pk;
      vec4 ak;
      interior(corner, n, k, pk, ak);
      p += pk;
      a += ak;
    }
    p /= float(n);
    a /= float(n);
  } else {
    vec3 p0, p1;
    vec4 a0, a1;
    interior(corner, n, 0u, p0, a0);
    interior(corner, n, role == 1 ? n - 1u : 1u, p1, a1);
    p = 0.5 * (p0 + p1);
    a = 0.5 * (a0 + a1);
  }
}

vec3 b[16];  // this patch's Bezier points

// d/du of the patch is a positive combination of the 12 row differences, d/dv of the 12 column differences,
// so its normal (d/du x d/dv) lies in the cone of their 144 cross products.
const int kNormalCandidates = 144;
vec3 normalCandidate(int k) {
  int i = k / 12, j = k % 12;
  vec3 du = b[(i / 3) * 4 + i % 3 + 1] - b[(i / 3) * 4 + i % 3];
  vec3 dv = b[(j / 4 + 1) * 4 + j % 4] - b[(j / 4) * 4 + j % 4];
  return cross(du, dv);
}

#include "normal_cone.glsl"

void main() {
  uint patchIndex = gl_GlobalInvocationID.x;
  if (patchIndex >= pass.primitiveCount) return;
  record = patches[patchIndex];
  uint base = patchIndex * uint(ARBOR_ACC_CONTROL_VEC4S);
  float radius = 0.0;
  for (int id = 0; id < 16; ++id) {
    vec4 a;
    controlPoint(id, b[id], a);
    control[base + uint(id)] = vec4(b[id], a.w);
    control[base + 16u + uint(id)] = vec4(a.xyz, 0.0);
    radius = max(radius, a.w);
  }
  for (int i = 0; i < 4; ++i) {
    control[base + 32u + uint(i)] = vec4(record.w == 2u ? vec3(0.0) : limitNormal(i), 0.0);
    control[base + 36u + uint(i)] = vec4(vertices[cornerVertex(i)].uvw.xyz, 0.0);
  }

  // The hull: the box of the control points (the patch lies in their convex hull) and the cone of its normals.
  vec3 lo = b[0], hi = b[0];
  for (int i = 1; i < 16; ++i) {
    lo = min(lo, b[i]);
    hi = max(hi, b[i]);
  }
  hulls[3u * patchIndex] = vec4(lo, radius);
  hulls[3u * patchIndex + 1u] = vec4(hi, 0.0);
  hulls[3u * patchIndex + 2u] = normalCone();
}
