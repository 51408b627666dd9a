#version 450
// PN-triangles: the control stage fetches each triangle's corners itself, so the vertex stage has nothing to do.

void main() { gl_Position = vec4(0.0); }
