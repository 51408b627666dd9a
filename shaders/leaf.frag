#version 450
#extension GL_GOOGLE_include_directive : require
// Leaf shading after Kharlamov et al.: lit from the front, translucent yellow-green when the sun is behind the
// leaf as seen from the eye, a specular highlight when it reflects the sun; all direct light times the
// self-shadowing factor.

#include "scene.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) flat in vec3 worldNormal;
layout(location = 2) in vec2 atlasCoordinate;
layout(location = 3) flat in float lightReaching;

layout(location = 0) out vec4 color;

void main() {
  vec4 texel = texture(leafAtlas, atlasCoordinate);  // the sampler caps the MIP level (renderer.cpp)
  if (texel.a < 0.5) discard;
  vec3 albedo = texel.rgb;
  vec3 n = normalize(worldNormal);
  vec3 v = normalize(scene.cameraPos.xyz - worldPosition);
  if (dot(n, v) < 0.0) n = -n;  // the side facing the eye
  vec3 l = normalize(scene.lightDir.xyz);
  float sun = scene.lightDir.w * lightReaching;
  float front = max(dot(n, l), 0.0);
  float back = max(dot(-n, l), 0.0);  // the sun shines through the leaf towards the eye
  vec3 translucent = vec3(0.75, 0.85, 0.25) * albedo * 1.6;
  vec3 h = normalize(l + v);
  float specular = front > 0.0 ? 0.18 * pow(max(dot(n, h), 0.0), 24.0) : 0.0;
  vec3 sky = mix(scene.ground.rgb * 0.6, scene.skyTop.rgb, 0.5 + 0.5 * n.z);
  vec3 lit = albedo * (0.55 * sky) + sun * (albedo * front * vec3(1.0, 0.96, 0.88) + translucent * back + specular);
  color = vec4(pow(lit, vec3(1.0 / 2.2)), 1.0);
}
