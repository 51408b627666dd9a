#version 450
#extension GL_GOOGLE_include_directive : require
// Sky: by the elevation of the view ray, from the horizon colour (where the ground fades into it) to the zenith.

#include "scene.glsl"

layout(location = 0) in vec2 screen;
layout(location = 0) out vec4 color;

void main() {
  vec4 far = scene.inverseViewProj * vec4(screen * 2.0 - 1.0, 1.0, 1.0);
  vec3 ray = normalize(far.xyz / far.w - scene.cameraPos.xyz);
  vec3 c = mix(scene.skyHorizon.rgb, scene.skyTop.rgb, smoothstep(0.0, 0.5, ray.z));
  color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
