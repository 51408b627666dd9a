#version 450
#extension GL_GOOGLE_include_directive : require
// Ground: lit by the sun, fading with distance from the eye into the sky's horizon colour (no visible edge).

#include "scene.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 color;

void main() {
  float sun = max(normalize(scene.lightDir.xyz).z, 0.0) * scene.lightDir.w;
  vec3 c = scene.ground.rgb * (0.45 + 0.55 * sun);
  float fog = smoothstep(0.0, 1.0, length(worldPosition - scene.cameraPos.xyz) / scene.ground.w);
  color = vec4(pow(mix(c, scene.skyHorizon.rgb, fog), vec3(1.0 / 2.2)), 1.0);
}
