#version 450
// Ceiling fragments: one constant colour, no texture, no lighting.

layout(location = 0) out vec4 color;

void main() { color = vec4(0.4, 0.3, 0.2, 1.0); }
