// The scene uniforms and the tree vertex, shared by the graphics stages (scene.glsl) and the compute passes
// (compute.glsl).
#include "interface.h"

layout(set = 0, binding = ARBOR_BINDING_SCENE, std140) uniform Scene {
  mat4 viewProj;
  mat4 view;
  mat4 inverseViewProj;
  vec4 cameraPos;     // xyz
  vec4 lightDir;      // xyz towards the sun, w intensity
  vec4 viewport;      // width, height, 1/width, 1/height
  vec4 tess;          // uniform level, adaptive target edge in pixels (0: off), max level, cull (1: on)
  vec4 displace;      // scale, bias, seam fade width (in |w|), texture repeats per unit of v
  vec4 skyTop;
  vec4 skyHorizon;
  vec4 ground;        // rgb, distance from the eye at which it has faded into the horizon (metres)
  uvec4 flags;        // x: unused (capture is a pipeline variant), y: wireframe colouring, z: back faces in magenta
  vec4 lens;          // x: pixels covered by one unit of length at unit distance
  vec4 leafLod;       // distance (m) up to which all leaves show (0: no thinning), density, unused, shadow leaves
  vec4 wind;          // unit direction xy (z up), strength (0: still), gust frequency (Hz)
  vec4 windClock;     // x: seconds into the gust period (every motion repeats with it)
} scene;

struct TreeVertex {
  vec4 positionRadius;  // object space, branch radius
  vec4 normalLevel;     // unit normal, stem level
  vec4 uvw;             // u mirrored front to back, v along the branch, w the flip coordinate
};


const float PI = 3.14159265358979;

// lavapipe (Mesa 22.3) inlines the push constants and uniforms that a branch depends on alone, and compiles the
// shader again each time they are rewritten (each draw or dispatch, each frame), keeping no compiled variant:
// such branches read them through runtime(), which it cannot see through (no bound buffer holds 2^31 elements).
// scene.glsl and compute.glsl define it over a buffer every stage that includes them binds.
#define ARBOR_RUNTIME_OVER(bufferLength)                                            \
  uint runtime(uint x) { return x | (uint(bufferLength) & 0x80000000u); }          \
  float runtime(float x) { return uintBitsToFloat(runtime(floatBitsToUint(x))); }
