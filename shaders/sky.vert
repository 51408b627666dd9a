#version 450
// A triangle covering the screen, behind everything.

layout(location = 0) out vec2 screen;

void main() {
  vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
  screen = p;
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
