#version 450
#extension GL_GOOGLE_include_directive : require
// Every frame, per patch of one instance: cull it (hull outside the view, or every normal facing away), set
// its edge factors (uniform, or adaptive from each edge's own end points so neighbours agree), and append it to
// the bucket of its largest factor; draw_commands.comp then turns the buckets into indirect draws.

#include "compute.glsl"

layout(local_size_x = ARBOR_COMPUTE_GROUP) in;

vec4 toClip(vec3 objectPosition) { return scene.viewProj * (pass.model * vec4(objectPosition, 1.0)); }

// Tessellation factor of an edge from its two end points only, so the patches on both sides agree (no
// cracks), rounded up as equal spacing rounds it.
uint edgeFactor(vec3 a, vec3 b) {
  if (runtime(scene.tess.y) <= 0.0) return uint(ceil(scene.tess.x));
  vec4 ca = toClip(a), cb = toClip(b);
  if (ca.w <= 1e-3 || cb.w <= 1e-3) return uint(ceil(scene.tess.z));  // crosses the eye plane: as fine as allowed
  float pixels = length((ca.xy / ca.w - cb.xy / cb.w) * 0.5 * scene.viewport.xy);
  return uint(ceil(clamp(pixels / scene.tess.y, 1.0, scene.tess.z)));
}

// A box of points entirely outside one clip plane is not drawn.
bool outsideFrustum(vec3 lo, vec3 hi) {
  vec4 c[8];
  for (int i = 0; i < 8; ++i) c[i] = toClip(vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z));
  for (int axis = 0; axis < 3; ++axis) {
    bool allBelow = true, allAbove = true;
    for (int i = 0; i < 8; ++i) {
      // Vulkan clip space: -w < x, y < w and 0 < z < w.
      allBelow = allBelow && c[i][axis] < (axis == 2 ? 0.0 : -c[i].w);
      allAbove = allAbove && c[i][axis] > c[i].w;
    }
    if (allAbove || allBelow) return true;
  }
  return false;
}

// Every point of the box's bounding sphere sees every normal of the cone from behind: with angle(axis, d) below
// 90 degrees minus the cone's half angle for every eye-to-point d, no normal faces the eye.
bool facingAway(vec3 lo, vec3 hi, vec4 cone) {
  if (cone.w > 1.0) return false;
  vec3 eye = (inverse(pass.model) * vec4(scene.cameraPos.xyz, 1.0)).xyz;  // object space: the sign is affine-invariant
  vec3 centre = 0.5 * (lo + hi);
  float radius = 0.5 * length(hi - lo);
  vec3 d = centre - eye;
  return dot(cone.xyz, d) - radius > cone.w * (length(d) + radius);
}

void main() {
  uint flags = runtime(pass.flags);
  uint primitive = gl_GlobalInvocationID.x;
  if (primitive >= pass.primitiveCount) return;
  vec4 low = hulls[3u * primitive], high = hulls[3u * primitive + 1u], cone = hulls[3u * primitive + 2u];
  float reach = low.w * abs(scene.displace.x);  // the largest displacement, (d - b) r s with |d - b| <= 1
  vec3 lo = low.xyz - reach, hi = high.xyz + reach;
  if ((flags & kCullFrustum) != 0u && outsideFrustum(lo, hi)) return;
  if ((flags & kCullBackFaces) != 0u && facingAway(lo, hi, cone)) return;

  uvec4 factor;
  if ((flags & kTriangles) != 0u) {
    vec3 p0 = vertices[triangleIndices[3u * primitive]].positionRadius.xyz;
    vec3 p1 = vertices[triangleIndices[3u * primitive + 1u]].positionRadius.xyz;
    vec3 p2 = vertices[triangleIndices[3u * primitive + 2u]].positionRadius.xyz;
    // Outer level i is the edge opposite corner i.
    factor = uvec4(edgeFactor(p1, p2), edgeFactor(p2, p0), edgeFactor(p0, p1), 1u);
  } else {
    uint offset = patches[primitive].x;
    vec3 c0 = vertices[points[offset]].positionRadius.xyz, c1 = vertices[points[offset + 1u]].positionRadius.xyz;
    vec3 c2 = vertices[points[offset + 2u]].positionRadius.xyz, c3 = vertices[points[offset + 3u]].positionRadius.xyz;
    // Outer levels: u = 0 (corners 0-3), v = 0 (0-1), u = 1 (1-2), v = 1 (3-2), each from its own end points.
    factor = uvec4(edgeFactor(c0, c3), edgeFactor(c0, c1), edgeFactor(c1, c2), edgeFactor(c3, c2));
  }
  uint largest = max(max(factor.x, factor.y), max(factor.z, factor.w));
  uint bucket = largest <= 1u && (flags & kCornerBucket) != 0u ? 0u
                : (flags & kBuckets) == 0u                     ? 1u
                                                               : uint(findMSB(max(largest, 2u) - 1u)) + 1u;
  uint slot = atomicAdd(counts[pass.counterBase + bucket], 1u);
  visible[pass.listBase + bucket * pass.primitiveCount + slot] =
      uvec2(primitive, factor.x | (factor.y << 8) | (factor.z << 16) | (factor.w << 24));
}
