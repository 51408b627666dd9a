#version 450
#extension GL_GOOGLE_include_directive : require
// Bark: colour and bump from the flip-coordinate texture lookup, lit by the sun and the sky.

#include "scene.glsl"
#include "bark.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec3 uvw;
layout(location = 3) in float radius;

layout(location = 0) out vec4 color;

void main() {
  if (scene.flags.z != 0u && !gl_FrontFacing) {  // seen through a crack in the closed surface
    color = vec4(1.0, 0.0, 1.0, 1.0);
    return;
  }
  vec2 tc = barkCoordinates(uvw);
  // The wrapped u jumps where the flip coordinate changes sign; its shifted twin is continuous there, so the
  // smaller of the two derivatives gives the texture level (a manually chosen MIP level at flip seams).
  vec2 dx = dFdx(tc), dy = dFdy(tc);
  float shifted = fract(tc.x + 0.5);
  float sdx = dFdx(shifted), sdy = dFdy(shifted);
  if (abs(sdx) < abs(dx.x)) dx.x = sdx;
  if (abs(sdy) < abs(dy.x)) dy.x = sdy;
  vec4 bark = textureGrad(barkColor, tc, dx, dy);  // colour, and the height in alpha: one lookup (renderer.cpp)
  vec3 albedo = bark.rgb;

  vec3 n = dot(worldNormal, worldNormal) > 1e-30 ? normalize(worldNormal) : vec3(0.0, 0.0, 1.0);
  if (!gl_FrontFacing) n = -n;
  // Bump mapping from the height texture through screen-space derivatives (no tangent frame needed).
  float h = bark.a;
  vec3 dpdx = dFdx(worldPosition), dpdy = dFdy(worldPosition);
  vec3 r1 = cross(dpdy, n), r2 = cross(n, dpdx);
  float det = dot(dpdx, r1);
  float strength = radius * (0.15 + 2.0 * scene.displace.x) * seamFade(uvw.z);
  vec3 gradient = sign(det) * (dFdx(h) * r1 + dFdy(h) * r2);
  vec3 bumped = abs(det) * n - strength * gradient;
  if (abs(det) > 1e-20 && dot(bumped, bumped) > 1e-30) n = normalize(bumped);

  color = vec4(scene.flags.y != 0u ? pow(vec3(0.05), vec3(1.0 / 2.2)) : barkLighting(albedo, n), 1.0);  // y: wireframe
}
