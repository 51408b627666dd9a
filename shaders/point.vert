#version 450
// Leaves: one point per leaf; the geometry stage reads the leaf and expands it, so only its index passes on.

layout(location = 0) flat out uint leafIndex;

void main() {
  leafIndex = uint(gl_VertexIndex);
  gl_Position = vec4(0.0);
}
