#version 450
#extension GL_GOOGLE_include_directive : require
// Curved PN triangles (Vlachos et al. 2001): a cubic Bezier triangle for position and a quadratic one for
// normals from each triangle's corners and vertex normals.

layout(vertices = 3) out;

#include "scene.glsl"

// The triangle's corners, fetched here from the index buffer as ACC fetches its 1-ring: one non-indexed
// draw path for both tessellated modes, split into draws the same way.
vec3 position[3];
vec3 normal[3];
vec4 uvwRadius[3];

layout(location = 0) out vec3 cornerPosition[];
layout(location = 1) out vec3 cornerNormal[];
layout(location = 2) out vec4 cornerUvwRadius[];
// b210 b120 b021 b012 b102 b201 b111, and n110 n011 n101
layout(location = 3) patch out vec3 cubic[7];
layout(location = 10) patch out vec3 quadratic[3];

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

void main() {
  for (int i = 0; i < 3; ++i) {
    TreeVertex v = vertices[triangleIndices[3u * (draw.patchBase + uint(gl_PrimitiveID)) + uint(i)]];
    position[i] = v.positionRadius.xyz;
    normal[i] = normalize(v.normalLevel.xyz);
    uvwRadius[i] = vec4(v.uvw.xyz, v.positionRadius.w);
  }
  cornerPosition[gl_InvocationID] = position[gl_InvocationID];
  cornerNormal[gl_InvocationID] = normal[gl_InvocationID];
  cornerUvwRadius[gl_InvocationID] = uvwRadius[gl_InvocationID];
  if (gl_InvocationID == 0) {
    vec3 b210 = edgePoint(0, 1), b120 = edgePoint(1, 0), b021 = edgePoint(1, 2), b012 = edgePoint(2, 1);
    vec3 b102 = edgePoint(2, 0), b201 = edgePoint(0, 2);
    vec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
    vec3 c = (position[0] + position[1] + position[2]) / 3.0;
    cubic[0] = b210;
    cubic[1] = b120;
    cubic[2] = b021;
    cubic[3] = b012;
    cubic[4] = b102;
    cubic[5] = b201;
    cubic[6] = e + (e - c) * 0.5;
    quadratic[0] = edgeNormal(0, 1);
    quadratic[1] = edgeNormal(1, 2);
    quadratic[2] = edgeNormal(2, 0);
    // Outer level i is the edge opposite corner i; each from its own end points, so neighbours agree.
    gl_TessLevelOuter[0] = edgeFactor(position[1], position[2]);
    gl_TessLevelOuter[1] = edgeFactor(position[2], position[0]);
    gl_TessLevelOuter[2] = edgeFactor(position[0], position[1]);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
    vec3 lo = min(position[0], min(position[1], position[2])), hi = max(position[0], max(position[1], position[2]));
    float grow = length(hi - lo) * 0.5;
    if (scene.tess.w > 0.0 && outsideFrustum(lo - grow, hi + grow)) {
      gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelInner[0] = 0.0;
    }
  }
}
