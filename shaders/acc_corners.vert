#version 450
#extension GL_GOOGLE_include_directive : require
// ACC patches whose every factor is 1, drawn without the tessellator: the two triangles the tessellator makes
// at factor 1, through the patch's corners, evaluated by the same code as acc.tese, so the picture is the same
// at a fraction of lavapipe's cost per tessellated patch. Six vertices per patch; gl_VertexIndex / 6 is its
// entry in this frame's list.

#include "scene.glsl"
#include "bark.glsl"
#include "acc_evaluate.glsl"

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

const uint kCorner[6] = uint[6](0u, 1u, 3u, 1u, 2u, 3u);  // the tessellator's split at factor 1 (lavapipe)
const vec2 kDomain[4] = vec2[4](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));

void main() {
  uint base = visible[uint(gl_VertexIndex) / 6u].x * uint(ARBOR_ACC_CONTROL_VEC4S);
  vec2 at = kDomain[kCorner[uint(gl_VertexIndex) % 6u]];
  vec3 point[16];
  vec4 attributes[16];
  for (uint i = 0u; i < 16u; ++i) {
    vec4 b = control[base + i];
    point[i] = b.xyz;
    attributes[i] = vec4(control[base + 16u + i].xyz, b.w);
  }
  vec3 normals[4], uvws[4];
  for (uint i = 0u; i < 4u; ++i) {
    normals[i] = control[base + 32u + i].xyz;
    uvws[i] = control[base + 36u + i].xyz;
  }
  AccPoint surface = evaluateAcc(point, attributes, normals, uvws, at.x, at.y);
  vec3 p = surface.position;
  uvw = surface.uvw;
  radius = surface.radius;
  if (scene.displace.x != 0.0) p += surface.along * displacement(uvw, radius, displacementLod(p, radius));
  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * surface.normal;
  gl_Position = scene.viewProj * world;
}
