#version 450
// ACC: the control shader fetches each patch's 1-ring itself, so the vertex stage has nothing to do.

void main() { gl_Position = vec4(0.0); }
