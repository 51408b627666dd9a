#version 450
#extension GL_GOOGLE_include_directive : require
// Loop & Schaefer's approximation of Catmull-Clark (ACC): from a quad and its 1-ring, the 16 control points
// of a bicubic Bezier patch, one per invocation. Regular patches come out exactly as their B-spline.
// The same construction, in the same order, is generator/patches/acc.cpp (the CPU reference).

layout(vertices = 16) out;

#include "scene.glsl"

layout(location = 0) out vec3 bezierPosition[];
layout(location = 1) out vec4 bezierUvwRadius[];       // u, v, w and radius follow the same construction
layout(location = 2) patch out vec3 cornerNormal[4];   // exact Catmull-Clark limit normals at the corners
layout(location = 6) patch out vec3 cornerUvw[4];      // corner texture coordinates, for the seam-safe mix

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

void main() {
  uint patchIndex = uint(gl_PrimitiveID) + draw.patchBase;
  record = patches[patchIndex];
  int id = gl_InvocationID;  // per-vertex outputs may only be written at [gl_InvocationID]
  int row = id / 4, column = id % 4;

  vec3 p;
  vec4 a;
  if (record.w == 2u) {
    // Fallback (open boundary): the bilinear quad through the corners.
    vec2 t = vec2(float(column), float(row)) / 3.0;
    uint c0 = cornerVertex(0), c1 = cornerVertex(1), c2 = cornerVertex(2), c3 = cornerVertex(3);
    p = mix(mix(positionOf(c0), positionOf(c1), t.x), mix(positionOf(c3), positionOf(c2), t.x), t.y);
    a = mix(mix(attributeOf(c0), attributeOf(c1), t.x), mix(attributeOf(c3), attributeOf(c2), t.x), t.y);
  } else {
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
  bezierPosition[gl_InvocationID] = p;
  bezierUvwRadius[gl_InvocationID] = a;

  if (id < 4) {
    cornerNormal[id] = record.w == 2u ? vec3(0.0) : limitNormal(id);
    cornerUvw[id] = vertices[cornerVertex(id)].uvw.xyz;
  }
  barrier();

  if (id == 0) {
    vec3 c0 = positionOf(cornerVertex(0)), c1 = positionOf(cornerVertex(1));
    vec3 c2 = positionOf(cornerVertex(2)), c3 = positionOf(cornerVertex(3));
    // Outer levels: u = 0 (corners 0-3), v = 0 (0-1), u = 1 (1-2), v = 1 (3-2), each from its own end points.
    float l0 = edgeFactor(c0, c3), l1 = edgeFactor(c0, c1), l2 = edgeFactor(c1, c2), l3 = edgeFactor(c3, c2);
    // A patch outside the view (its control points, grown by the largest displacement) is not tessellated.
    vec3 lo = bezierPosition[0], hi = bezierPosition[0];
    float radius = 0.0;
    for (int i = 1; i < 16; ++i) {
      lo = min(lo, bezierPosition[i]);
      hi = max(hi, bezierPosition[i]);
      radius = max(radius, bezierUvwRadius[i].w);
    }
    float margin = radius * abs(scene.displace.x);
    if (scene.tess.w > 0.0 && outsideFrustum(lo - margin, hi + margin)) l0 = l1 = l2 = l3 = 0.0;
    gl_TessLevelOuter[0] = l0;
    gl_TessLevelOuter[1] = l1;
    gl_TessLevelOuter[2] = l2;
    gl_TessLevelOuter[3] = l3;
    gl_TessLevelInner[0] = max(l1, l3);
    gl_TessLevelInner[1] = max(l0, l2);
  }
}
