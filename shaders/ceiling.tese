#version 450
#extension GL_GOOGLE_include_directive : require
// Ceiling evaluation: the bilinear quad between the patch's corner points, the same domain and spacing as ACC's.

layout(quads, equal_spacing, ccw) in;

#include "scene.glsl"

layout(location = 0) patch in uint patchIndex;

void main() {
  uint base = patchIndex * uint(ARBOR_ACC_CONTROL_VEC4S);
  vec2 uv = gl_TessCoord.xy;
  vec3 p = mix(mix(control[base].xyz, control[base + 3u].xyz, uv.x), mix(control[base + 12u].xyz, control[base + 15u].xyz, uv.x), uv.y);
  gl_Position = scene.viewProj * (draw.model * vec4(p, 1.0));
}
