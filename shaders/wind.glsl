// Wind (docs/wind.md): how far a point moves, from its rest position and its wind record. The same function as
// generator/tree/wind.cpp's windOffset, which the tests hold this to. Needs the scene uniforms.

// Whether this pipeline's vertex stage moves with the wind: set per pipeline variant (interface.h), as lavapipe
// would run the wind code for every vertex in still air too.
layout(constant_id = ARBOR_SPEC_WIND) const bool kWind = false;

// Radians into the gust period at this frame.
float windAngle() { return 2.0 * PI * scene.wind.w * scene.windClock.x; }

// reach.w: the tree's phase in the gusts (the same in all its records).
vec3 windOffset(vec3 rest, vec4 reach, vec4 phase, float treeHeight) {
  if (scene.wind.z <= 0.0 || treeHeight <= 0.0) return vec3(0.0);
  const float kSway[3] = float[3](0.10, 0.16, 0.24);
  const float kHarmonic[3] = float[3](3.0, 5.0, 7.0);
  vec3 along = vec3(scene.wind.xy, 0.0), side = vec3(-scene.wind.y, scene.wind.x, 0.0), up = vec3(0.0, 0.0, 1.0);
  float w = windAngle() + reach.w;
  float gust = 0.65 + 0.25 * sin(w) + 0.10 * sin(2.0 * w + 1.3);
  // The trunk bends as a cantilever and keeps each point's distance from the base.
  float z = max(rest.z, 0.0);
  float h = min(z / treeHeight, 1.5);
  float bend = scene.wind.z * gust * 0.04 * treeHeight * h * h;
  vec3 offset = along * bend - up * (0.5 * bend * bend / max(z, 1e-6));
  for (int l = 0; l < 3; ++l) {
    if (reach[l] <= 0.0) continue;
    float sway = sin(kHarmonic[l] * w + phase[l]), across = sin(kHarmonic[l] * w + phase[l] + 1.7);
    offset += scene.wind.z * kSway[l] * reach[l] * (along * (0.6 * gust + 0.4 * sway) + side * (0.3 * across) + up * (0.15 * sway));
  }
  return offset;
}

// A leaf tip's flutter along the blade's normal, in blade lengths.
float leafFlutter(float phase) { return scene.wind.z * 0.25 * sin(11.0 * windAngle() + phase); }
