#version 450
#extension GL_GOOGLE_include_directive : require
// PN-triangle evaluation: cubic position, quadratic normal, linear texture coordinates and radius.

layout(triangles, equal_spacing, ccw) in;

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) patch in uint triangle;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

void main() {
  // The triangle's record in the control buffer (interface.h).
  uint base = triangle * uint(ARBOR_PN_CONTROL_VEC4S);
  vec3 cornerPosition[3], cornerNormal[3], cubic[7], quadratic[3];
  vec4 cornerUvwRadius[3];
  for (int i = 0; i < 3; ++i) {
    cornerPosition[i] = control[base + uint(i)].xyz;
    cornerNormal[i] = control[base + 10u + uint(i)].xyz;
    quadratic[i] = control[base + 13u + uint(i)].xyz;
    cornerUvwRadius[i] = vec4(control[base + 16u + uint(i)].xyz, control[base + uint(i)].w);
  }
  for (int i = 0; i < 7; ++i) cubic[i] = control[base + 3u + uint(i)].xyz;
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
  p += n * displacement(uvw, radius, displacementLod(p, radius));
  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * n;
  gl_Position = scene.viewProj * world;
}
