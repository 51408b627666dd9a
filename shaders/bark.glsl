// Bark texturing with the flip coordinate (Nystad 6.3.2, 6.4.1): u is mirrored front to back, so the side
// with w < 0 reads the texture flipped and the texture wraps once around the branch without a seam.

// Whether this pipeline displaces (scene.displace.x is then not 0): set per pipeline variant (interface.h).
layout(constant_id = ARBOR_SPEC_DISPLACED) const bool kDisplaced = false;

vec2 barkCoordinates(vec3 uvw) {
  float u = uvw.z >= 0.0 ? 0.5 * uvw.x : 1.0 - 0.5 * uvw.x;
  return vec2(u, uvw.y * scene.displace.w);
}

// Near the seams (|w| small) displacement and bump fade out, so both sides agree there.
float seamFade(float w) {
  return scene.displace.z > 0.0 ? smoothstep(0.0, scene.displace.z, abs(w)) : 1.0;
}

// Texture level for displacement, about one texel per tessellated segment, and the same wherever patches share
// a point, or the displaced surface would crack. Uniform factors: a patch side spans a quarter turn of the
// branch (a quarter of the texture's width) cut into the same number of segments everywhere. Adaptive
// factors: a segment is about the target's pixels long, which each point knows from its distance and radius
// (the texture's width wraps once around the branch).
float displacementLod(vec3 objectPosition, float radius) {
  float width = float(textureSize(barkHeight, 0).x);
  float texelsPerSegment;
  if (runtime(scene.tess.y) > 0.0) {
    float distance = length((draw.model * vec4(objectPosition, 1.0)).xyz - scene.cameraPos.xyz);
    float segment = scene.tess.y * distance / scene.lens.x;
    texelsPerSegment = segment * width / (2.0 * PI * max(radius, 1e-6));
  } else {
    texelsPerSegment = 0.25 * width / max(scene.tess.x, 1.0);
  }
  return max(0.0, log2(max(texelsPerSegment, 1.0)));
}

// Bilinear height from one MIP level, filtered here from texel fetches: on lavapipe both the sampler's
// filtering and textureSize at a per-point level gave two patches different heights at the same
// coordinates, which cracked the displaced surface. The level's size comes from level 0's.
float bilinearHeight(vec2 tc, int level) {
  ivec2 size = max(textureSize(barkHeight, 0) >> level, ivec2(1));
  vec2 x = tc * vec2(size) - 0.5;
  ivec2 i0 = ivec2(floor(x));
  vec2 f = x - vec2(i0);
  ivec2 a = (i0 % size + size) % size, b = (a + 1) % size;  // the texture repeats both ways
  float h00 = texelFetch(barkHeight, ivec2(a.x, a.y), level).r, h10 = texelFetch(barkHeight, ivec2(b.x, a.y), level).r;
  float h01 = texelFetch(barkHeight, ivec2(a.x, b.y), level).r, h11 = texelFetch(barkHeight, ivec2(b.x, b.y), level).r;
  return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

// Trilinear height: two MIP levels around `lod`, blended.
float heightAt(vec2 tc, float lod) {
  int top = textureQueryLevels(barkHeight) - 1;
  float l = clamp(lod, 0.0, float(top));
  int l0 = int(floor(l));
  int l1 = min(l0 + 1, top);
  return mix(bilinearHeight(tc, l0), bilinearHeight(tc, l1), l - float(l0));
}

// Displacement along the normal (5.5.1): (d - b) r s, faded at seams. Called only where kDisplaced.
float displacement(vec3 uvw, float radius, float lod) {
  float d = heightAt(barkCoordinates(uvw), lod);
  return (d - scene.displace.y) * radius * scene.displace.x * seamFade(uvw.z);
}

// Sun and sky on bark of this albedo with shading normal n, gamma-encoded for the 8-bit target.
vec3 barkLighting(vec3 albedo, vec3 n) {
  vec3 l = normalize(scene.lightDir.xyz);
  float sun = max(dot(n, l), 0.0) * scene.lightDir.w;
  vec3 sky = mix(scene.ground.rgb * 0.6, scene.skyTop.rgb, 0.5 + 0.5 * n.z);
  return pow(albedo * (1.2 * sun * vec3(1.0, 0.96, 0.88) + 0.6 * sky), vec3(1.0 / 2.2));
}
