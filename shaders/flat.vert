#version 450
#extension GL_GOOGLE_include_directive : require
// The coarse mesh as it is (flat mode).

#include "scene.glsl"
#include "wind.glsl"

layout(location = 0) in vec4 positionRadius;
layout(location = 1) in vec4 normalLevel;
layout(location = 2) in vec4 texture;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

void main() {
  // The wind moves each vertex once (flat mode has no control points to rebuild).
  vec3 position = positionRadius.xyz;
  if (kWind && draw.windHeight > 0.0) {
    uint w = ARBOR_WIND_VEC4S * uint(gl_VertexIndex);
    position += windOffset(position, windPoints[w], windPoints[w + 1u], draw.windHeight);
  }
  vec4 world = draw.model * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * normalLevel.xyz;
  uvw = texture.xyz;
  radius = positionRadius.w;
  gl_Position = scene.viewProj * world;
}
