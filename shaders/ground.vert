#version 450
#extension GL_GOOGLE_include_directive : require
// The ground: a square at height 0 around the eye, four fade distances wide each way (two triangles).

#include "scene.glsl"

layout(location = 0) out vec3 worldPosition;

const vec2 kCorners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));

void main() {
  worldPosition = vec3(scene.cameraPos.xy + kCorners[gl_VertexIndex] * 4.0 * scene.ground.w, 0.0);
  gl_Position = scene.viewProj * vec4(worldPosition, 1.0);
}
