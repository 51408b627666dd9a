#version 450
#extension GL_GOOGLE_include_directive : require
// Fake branches shaded as the cylinders they stand for: the normal turns from the eye towards the sides across
// the rectangle, and the visible half of the bark texture wraps over it, lit like the mesh.

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) in vec2 acrossAndV;
layout(location = 1) flat in vec3 sideways;
layout(location = 2) flat in vec3 facing;

layout(location = 0) out vec4 color;

void main() {
  float s = clamp(acrossAndV.x, -1.0, 1.0);
  vec3 n = normalize(sideways * s + facing * sqrt(max(1.0 - s * s, 0.0)));
  // u runs over the half turn that faces the eye (the flip coordinate's front side).
  vec2 tc = barkCoordinates(vec3(acos(-s) / PI, acrossAndV.y, 1.0));
  vec3 albedo = texture(barkColor, tc).rgb;
  color = vec4(barkLighting(albedo, n), 1.0);
}
