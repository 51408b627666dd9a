#version 450
#extension GL_GOOGLE_include_directive : require
// Leaves (Nystad 5.5.3, 6.5): each leaf is a card textured with its kind's cell of the leaf atlas.
// Distance thins the leaves by their place in the random order, so clusters never pop out whole; the first
// `shadowLeaves` of that order shade the others (self-shadowing).

#include "scene.glsl"
#include "wind.glsl"
#include "card.glsl"

layout(location = 0) out vec3 worldPosition;
layout(location = 1) flat out vec3 worldNormal;     // one per card
layout(location = 2) out vec2 atlasCoordinate;
layout(location = 3) flat out float lightReaching;  // 1: unshadowed, 0: behind another leaf

void main() {
  uint i = cardIndex();
  Leaf leaf = leaves[i];
  // The wind moves the blade's base with its node and flutters its tip along its normal.
  vec3 restBase = leaf.positionLength.xyz;
  float flutter = 0.0;
  if (kWind && draw.windHeight > 0.0) {
    uint w = draw.leafWindBase + ARBOR_WIND_VEC4S * i;
    restBase += windOffset(restBase, windPoints[w], windPoints[w + 1u], draw.windHeight);
    flutter = leafFlutter(windPoints[w + 1u].w);
  }
  vec3 base = (draw.model * vec4(restBase, 1.0)).xyz;
  float eyeDistance = length(base - scene.cameraPos.xyz);
  // Fraction of the leaves kept at this distance: all up to leafLod.x metres, then falling with the square of
  // the distance (as the crown's area on screen); the last tenth of the kept ones shrink away. The kept leaves
  // grow by the inverse square root of the share thinned away, so the crown keeps its leaf area (stochastic
  // simplification, Cook et al. 2007), at most twice as long and wide.
  float thinned = scene.leafLod.x > 0.0 ? min(1.0, pow(scene.leafLod.x / max(eyeDistance, 1e-3), 2.0)) : 1.0;
  float kept = scene.leafLod.y * thinned;
  float rank = (float(i) + 0.5) / max(float(draw.leafCount), 1.0);
  if (rank > kept) {
    gl_Position = kNoCard;
    return;
  }
  float size = scene.leafLod.x > 0.0 ? clamp((kept - rank) / (0.1 * kept), 0.0, 1.0) * min(inversesqrt(thinned), 2.0) : 1.0;

  vec3 along = mat3(draw.model) * (leaf.directionWidth.xyz + leaf.normalKind.xyz * flutter);
  vec3 normal = normalize(mat3(draw.model) * leaf.normalKind.xyz);
  vec3 across = normalize(cross(normal, along));
  // The blade fills only part of its atlas cell's width: widen the quad so the blade has the leaf's width.
  const float kBladeShare[4] = float[4](0.82, 0.30, 0.95, 0.70);
  uint kind = min(uint(leaf.normalKind.w), 3u);
  float bladeLength = leaf.positionLength.w * size, halfWidth = leaf.directionWidth.w * size / kBladeShare[kind];
  // Far leaves narrower than about a pixel would vanish between the samples: enlarge them to a pixel wide (at
  // most 4 times), so a distant crown keeps its coverage.
  float pixels = leaf.directionWidth.w * size * scene.lens.x / max(eyeDistance, 1e-3);  // the blade's half width
  if (pixels > 0.0 && pixels < 0.75) {
    float grow = min(0.75 / pixels, 4.0);
    halfWidth *= grow;
    bladeLength *= grow;
  }

  // Self-shadowing against the first leaves of the random order: c = saturate(1 - 100 (b_dot - 0.99)).
  // A flat output: only the provoking corner pays for the loop.
  float c = 1.0;
  uint count = cardProvoking() ? min(uint(scene.leafLod.w), draw.leafCount) : 0u;
  vec3 l = normalize(scene.lightDir.xyz);
  for (uint j = 0u; j < count; ++j) {
    if (j == i) continue;
    vec3 towards = (draw.model * vec4(leaves[j].positionLength.xyz, 1.0)).xyz - base;
    float d = length(towards);
    if (d < 1e-4) continue;
    float bDot = dot(towards / d, l);
    c = min(c, clamp(1.0 - 100.0 * (bDot - 0.99), 0.0, 1.0));
  }

  vec2 cell = vec2(float(kind % 2u), float(kind / 2u)) * 0.5;
  uint corner = cardCorner();
  float s = (corner & 1u) != 0u ? 1.0 : -1.0;  // across
  float t = (corner & 2u) != 0u ? 1.0 : 0.0;   // base to tip
  worldPosition = base + along * bladeLength * t + across * halfWidth * s;
  worldNormal = normal;
  atlasCoordinate = cell + vec2(0.25 + 0.25 * s, 0.5 - 0.5 * t);
  lightReaching = c;
  gl_Position = scene.viewProj * vec4(worldPosition, 1.0);
}
