// The ACC surface at (u, v): the bicubic Bezier patch, the shading normal pulled to the exact limit normals
// towards the corners, seam-safe texture coordinates (Nystad 6.3.2), and the direction displacement moves
// along. The factor-1 corner pipeline (acc_corners.vert) does this arithmetic at the corners, in the same order.

struct AccPoint {
  vec3 position;  // on the patch, before displacement
  vec3 normal;    // shading normal, unit
  vec3 along;     // displacement direction: the blend of the corner limit normals
  vec3 uvw;       // seam-safe u, v, flip coordinate
  float radius;
};

vec3 safeNormalize(vec3 v) { return dot(v, v) > 1e-30 ? normalize(v) : vec3(0.0); }

void bernstein(float t, out vec4 b, out vec4 d) {
  float s = 1.0 - t;
  b = vec4(s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t);
  d = vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * s * t, 6.0 * s * t - 3.0 * t * t, 3.0 * t * t);
}

// `point` [row * 4 + column] with u along the columns (corner 0 -> 1) and v along the rows (corner 0 -> 3);
// `attributes`: their u, v, w and radius. Corner normals are zero for a fallback patch.
AccPoint evaluateAcc(vec3 point[16], vec4 attributes[16], vec3 cornerNormal[4], vec3 cornerUvw[4], float u, float v) {
  vec4 bu, du, bv, dv;
  bernstein(u, bu, du);
  bernstein(v, bv, dv);
  vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);
  vec4 a = vec4(0.0);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      vec3 b = point[row * 4 + column];
      p += bv[row] * bu[column] * b;
      pu += bv[row] * du[column] * b;
      pv += dv[row] * bu[column] * b;
      a += bv[row] * bu[column] * attributes[row * 4 + column];
    }
  }

  // Shading normal (as accNormal in generator/patches/acc.cpp): the geometry patch's normal (u runs corner
  // 0 -> 1, v corner 0 -> 3: counter-clockwise from outside), corrected towards the exact limit normal at each
  // corner by (limit normal - geometry normal there), weighted by that corner's Bernstein product.
  AccPoint result;
  vec3 n = safeNormalize(cross(pu, pv));
  float w[4] = float[4](bu.x * bv.x, bu.w * bv.x, bu.w * bv.w, bu.x * bv.w);
  bool limitNormals = any(notEqual(cornerNormal[0], vec3(0.0)));  // fallback patches have none
  if (limitNormals) {
    vec3 geometryAt[4] = vec3[4](safeNormalize(cross(point[1] - point[0], point[4] - point[0])),
                                 safeNormalize(cross(point[3] - point[2], point[7] - point[3])),
                                 safeNormalize(cross(point[15] - point[14], point[15] - point[11])),
                                 safeNormalize(cross(point[13] - point[12], point[12] - point[8])));
    for (int i = 0; i < 4; ++i) n += w[i] * (cornerNormal[i] - geometryAt[i]);
  }
  result.normal = safeNormalize(n);
  result.position = p;

  // Seam-safe texture coordinates: where |w| is small (near a seam) u comes from the corners directly.
  vec3 interpolated = mix(mix(cornerUvw[0], cornerUvw[1], u), mix(cornerUvw[3], cornerUvw[2], u), v);
  float flip = a.z;
  result.uvw = vec3(abs(flip) * a.x + (1.0 - abs(flip)) * interpolated.x, a.y, flip);
  result.radius = a.w;

  // On a shared edge the blend depends on that edge's two corners only, so neighbouring patches displace their
  // common points alike (the shading normal does not).
  result.along = limitNormals ? safeNormalize(mix(mix(cornerNormal[0], cornerNormal[1], u), mix(cornerNormal[3], cornerNormal[2], u), v))
                              : result.normal;
  return result;
}
