#version 450
#extension GL_GOOGLE_include_directive : require
// Wireframes drawn over the scene (the modeller's clouds, obstacles, attraction points and disabled branches):
// object-space position and colour per vertex, placed by the draw's model matrix.
#include "scene.glsl"

layout(location = 0) in vec4 position;
layout(location = 1) in vec4 color;
layout(location = 0) out vec3 lineColor;

void main() {
  lineColor = color.rgb;
  gl_Position = scene.viewProj * (draw.model * vec4(position.xyz, 1.0));
}
