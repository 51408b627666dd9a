#version 450
// Wireframes are unlit: their colour says what they are (which cloud, an obstacle, a disabled branch).

layout(location = 0) in vec3 lineColor;
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(lineColor, 1.0); }
