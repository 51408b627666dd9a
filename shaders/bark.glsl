// Bark texturing with the flip coordinate (Nystad 6.3.2, 6.4.1): u is mirrored front to back, so the side
// with w < 0 reads the texture flipped and the texture wraps once around the branch without a seam.

vec2 barkCoordinates(vec3 uvw) {
  float u = uvw.z >= 0.0 ? 0.5 * uvw.x : 1.0 - 0.5 * uvw.x;
  return vec2(u, uvw.y * scene.displace.w);
}

// Near the seams (|w| small) displacement and bump fade out, so both sides agree there.
float seamFade(float w) {
  return scene.displace.z > 0.0 ? smoothstep(0.0, scene.displace.z, abs(w)) : 1.0;
}

// Texture level for displacement, about one texel per tessellated segment: a patch side spans a quarter turn
// of the branch (a quarter of the texture's width) cut into `level` segments. (Also keeps lavapipe fast: a
// constant level 0 in these stages costs it seconds per frame.)
float displacementLod(float level) {
  float texelsPerSegment = 0.25 * float(textureSize(barkHeight, 0).x) / max(level, 1.0);
  return max(0.0, log2(max(texelsPerSegment, 1.0)));
}

// Displacement along the normal (5.5.1): (d - b) r s, faded at seams.
float displacement(vec3 uvw, float radius, float lod) {
  if (scene.displace.x == 0.0) return 0.0;
  float d = textureLod(barkHeight, barkCoordinates(uvw), lod).r;
  return (d - scene.displace.y) * radius * scene.displace.x * seamFade(uvw.z);
}
