#version 450
#extension GL_GOOGLE_include_directive : require
// ACC evaluation: the bicubic Bezier patch at the tessellated (u, v); normals from the patch's tangents,
// pulled to the exact limit normals towards the corners; texture coordinates with the seam-safe mix of the
// subdivided and the interpolated u (Nystad 6.3.2); displacement along the normal (5.5.1).

layout(quads, equal_spacing, ccw) in;

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) patch in uint patchIndex;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 uvw;
layout(location = 3) out float radius;

// Test hook: the evaluated points before and after displacement, with their patch and (u, v).
layout(set = 0, binding = ARBOR_BINDING_CAPTURE, std430) buffer Capture {
  uint count;
  uint capacity;
  uint pad0, pad1;
  vec4 entries[];  // triples: (patch, u, v, 0), (x, y, z, 0) on the patch, (x, y, z, flip) displaced
} capture;

vec3 safeNormalize(vec3 v) { return dot(v, v) > 1e-30 ? normalize(v) : vec3(0.0); }

void bernstein(float t, out vec4 b, out vec4 d) {
  float s = 1.0 - t;
  b = vec4(s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t);
  d = vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t);
}

// The patch's record in the control buffer (interface.h): Bezier points with radius, their (u, v, w), corner
// limit normals (zero for a fallback patch), the cage corners' (u, v, w).
uint base;
vec3 bezierPosition(int i) { return control[base + uint(i)].xyz; }

void main() {
  base = patchIndex * uint(ARBOR_ACC_CONTROL_VEC4S);
  vec3 cornerNormal[4], cornerUvw[4];
  for (int i = 0; i < 4; ++i) {
    cornerNormal[i] = control[base + 32u + uint(i)].xyz;
    cornerUvw[i] = control[base + 36u + uint(i)].xyz;
  }
  float u = gl_TessCoord.x, v = gl_TessCoord.y;
  vec4 bu, du, bv, dv;
  bernstein(u, bu, du);
  bernstein(v, bv, dv);
  vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);
  vec4 a = vec4(0.0);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      vec4 b4 = control[base + uint(row * 4 + column)];
      vec3 b = b4.xyz;
      p += bv[row] * bu[column] * b;
      pu += bv[row] * du[column] * b;
      pv += dv[row] * bu[column] * b;
      a += bv[row] * bu[column] * vec4(control[base + 16u + uint(row * 4 + column)].xyz, b4.w);
    }
  }

  // Shading normal (as accNormal in generator/patches/acc.cpp): the geometry patch's normal (u runs corner
  // 0 -> 1, v corner 0 -> 3: counter-clockwise from outside), corrected towards the exact limit normal at each
  // corner by (limit normal - geometry normal there), weighted by that corner's Bernstein product.
  vec3 n = safeNormalize(cross(pu, pv));
  float w[4] = float[4](bu.x * bv.x, bu.w * bv.x, bu.w * bv.w, bu.x * bv.w);
  if (any(notEqual(cornerNormal[0], vec3(0.0)))) {  // fallback patches have no corner normals
    vec3 geometryAt[4] = vec3[4](
        safeNormalize(cross(bezierPosition(1) - bezierPosition(0), bezierPosition(4) - bezierPosition(0))),
        safeNormalize(cross(bezierPosition(3) - bezierPosition(2), bezierPosition(7) - bezierPosition(3))),
        safeNormalize(cross(bezierPosition(15) - bezierPosition(14), bezierPosition(15) - bezierPosition(11))),
        safeNormalize(cross(bezierPosition(13) - bezierPosition(12), bezierPosition(12) - bezierPosition(8))));
    for (int i = 0; i < 4; ++i) n += w[i] * (cornerNormal[i] - geometryAt[i]);
  }
  n = safeNormalize(n);

  vec3 onPatch = p;

  // Seam-safe texture coordinates: where |w| is small (near a seam) u comes from the corners directly.
  vec3 interpolated = mix(mix(cornerUvw[0], cornerUvw[1], u), mix(cornerUvw[3], cornerUvw[2], u), v);
  float flip = a.z;
  uvw = vec3(abs(flip) * a.x + (1.0 - abs(flip)) * interpolated.x, a.y, flip);
  radius = a.w;

  // Displaced along the blend of the corner limit normals: on a shared edge it depends on that edge's two
  // corners only, so neighbouring patches move their common points alike (the shading normal does not).
  vec3 along = n;
  if (any(notEqual(cornerNormal[0], vec3(0.0)))) {
    along = safeNormalize(mix(mix(cornerNormal[0], cornerNormal[1], u), mix(cornerNormal[3], cornerNormal[2], u), v));
  }
  p += along * displacement(uvw, radius, displacementLod(p, radius));

  if (scene.flags.x != 0u) {
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
