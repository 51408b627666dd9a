#version 450
#extension GL_GOOGLE_include_directive : require
// Ceiling evaluation: the bilinear quad between the corners, the same domain and spacing as ACC's.

layout(quads, equal_spacing, ccw) in;

#include "scene.glsl"

layout(location = 0) in vec3 corner[];

void main() {
  vec2 uv = gl_TessCoord.xy;
  vec3 p = mix(mix(corner[0], corner[1], uv.x), mix(corner[3], corner[2], uv.x), uv.y);
  gl_Position = scene.viewProj * (draw.model * vec4(p, 1.0));
}
