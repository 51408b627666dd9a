// The cone of a patch's normals, for back-face culling: the patch's normal is a positive combination of the
// kNormalCandidates vectors normalCandidate(k) (declared by the includer), so it lies within any cone that holds
// them all. Returns (axis, sine of the half angle), or w = 2 when the cone is a half space or wider.
vec4 normalCone() {
  vec3 sum = vec3(0.0);
  for (int k = 0; k < kNormalCandidates; ++k) {
    vec3 c = normalCandidate(k);
    float length2 = dot(c, c);
    if (length2 > 1e-30) sum += c * inversesqrt(length2);
  }
  if (dot(sum, sum) < 1e-12) return vec4(0.0, 0.0, 1.0, 2.0);
  vec3 axis = normalize(sum);
  float lowest = 1.0;  // cosine of the widest angle between the axis and a candidate
  for (int k = 0; k < kNormalCandidates; ++k) {
    vec3 c = normalCandidate(k);
    float length2 = dot(c, c);
    if (length2 > 1e-30) lowest = min(lowest, dot(axis, c) * inversesqrt(length2));
  }
  // A little slack for rounding: a patch at the edge of facing away is kept.
  lowest -= 1e-3;
  if (lowest <= 0.0) return vec4(axis, 2.0);
  return vec4(axis, sqrt(max(0.0, 1.0 - lowest * lowest)));
}
