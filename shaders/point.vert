#version 450
// One point per leaf or fake-branch segment: the geometry stage reads its record and expands it, so only the
// index passes on.

layout(location = 0) flat out uint pointIndex;

void main() {
  pointIndex = uint(gl_VertexIndex);
  gl_Position = vec4(0.0);
}
