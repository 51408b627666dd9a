#version 450
#extension GL_GOOGLE_include_directive : require
// ACC evaluation: the patch at the tessellated (u, v) (acc_evaluate.glsl), displaced along the blended limit
// normals (Nystad 5.5.1).

layout(quads, equal_spacing, ccw) in;

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) in vec3 bezierPosition[];
layout(location = 1) in vec4 bezierUvwRadius[];
layout(location = 2) patch in vec3 cornerNormal[4];
layout(location = 6) patch in vec3 cornerUvw[4];
layout(location = 10) patch in uint patchIndex;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

// Test hook: the evaluated points before and after displacement, with their patch and (u, v); compiled in only
// in the capture variant (interface.h).
layout(constant_id = ARBOR_SPEC_CAPTURE) const bool kCapture = false;
layout(set = 0, binding = ARBOR_BINDING_CAPTURE, std430) buffer Capture {
  uint count;
  uint capacity;
  uint pad0, pad1;
  vec4 entries[];  // triples: (patch, u, v, 0), (x, y, z, 0) on the patch, (x, y, z, flip) displaced
} capture;

#include "acc_evaluate.glsl"

void main() {
  float u = gl_TessCoord.x, v = gl_TessCoord.y;
  vec3 point[16];
  vec4 attributes[16];
  for (int i = 0; i < 16; ++i) {
    point[i] = bezierPosition[i];
    attributes[i] = bezierUvwRadius[i];
  }
  vec3 normals[4] = vec3[4](cornerNormal[0], cornerNormal[1], cornerNormal[2], cornerNormal[3]);
  vec3 uvws[4] = vec3[4](cornerUvw[0], cornerUvw[1], cornerUvw[2], cornerUvw[3]);
  AccPoint surface = evaluateAcc(point, attributes, normals, uvws, u, v);
  vec3 onPatch = surface.position, p = surface.position, n = surface.normal;
  uvw = surface.uvw;
  radius = surface.radius;
  if (kDisplaced) p += surface.along * displacement(uvw, radius, displacementLod(p, radius));

  if (kCapture) {
    uint slot = atomicAdd(capture.count, 1u);
    if (slot < capture.capacity) {
      capture.entries[3u * slot] = vec4(float(patchIndex), u, v, uvw.x);
      capture.entries[3u * slot + 1u] = vec4(onPatch, uvw.y);
      capture.entries[3u * slot + 2u] = vec4(p, uvw.z);
    }
  }

  vec4 world = draw.model * vec4(p, 1.0);
  worldPosition = world.xyz;
  worldNormal = mat3(draw.model) * n;
  gl_Position = scene.viewProj * world;
}
