#version 450
#extension GL_GOOGLE_include_directive : require
// PN-triangle evaluation: cubic position, quadratic normal, linear texture coordinates and radius.

layout(triangles, equal_spacing, ccw) in;

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) in vec3 cornerPosition[];
layout(location = 1) in vec3 cornerNormal[];
layout(location = 2) in vec4 cornerUvwRadius[];
layout(location = 3) patch in vec3 cubic[7];
layout(location = 10) patch in vec3 quadratic[3];

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

void main() {
  float w = gl_TessCoord.x, u = gl_TessCoord.y, v = gl_TessCoord.z;  // weights of corners 0, 1, 2
  vec3 p = cornerPosition[0] * w * w * w + cornerPosition[1] * u * u * u + cornerPosition[2] * v * v * v +
           cubic[0] * 3.0 * w * w * u + cubic[1] * 3.0 * w * u * u + cubic[5] * 3.0 * w * w * v +
           cubic[2] * 3.0 * u * u * v + cubic[4] * 3.0 * w * v * v + cubic[3] * 3.0 * u * v * v +
           cubic[6] * 6.0 * w * u * v;
  vec3 n = cornerNormal[0] * w * w + cornerNormal[1] * u * u + cornerNormal[2] * v * v + quadratic[0] * w * u +
           quadratic[1] * u * v + quadratic[2] * w * v;
  n = normalize(n);
  vec4 a = cornerUvwRadius[0] * w + cornerUvwRadius[1] * u + cornerUvwRadius[2] * v;
  uvw = a.xyz;
  radius = a.w;
  if (kDisplaced) p += n * displacement(uvw, radius, displacementLod(p, radius));
  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * n;
  gl_Position = scene.viewProj * world;
}
