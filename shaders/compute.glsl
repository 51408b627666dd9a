// Shared by the compute passes: the scene uniforms, a tree's buffers, this frame's patch lists and the pass's
// push constants (compute set 0, bindings in interface.h).

#include "scene_uniforms.glsl"

#ifdef ARBOR_POSES_VERTICES
// wind.comp: writes the posed cage that the control-point passes then read as Vertices.
layout(set = 0, binding = ARBOR_COMPUTE_VERTICES, std430) writeonly buffer Vertices { TreeVertex vertices[]; };
layout(set = 0, binding = ARBOR_COMPUTE_REST, std430) readonly buffer Rest { TreeVertex rest[]; };
layout(set = 0, binding = ARBOR_COMPUTE_WIND, std430) readonly buffer Wind { vec4 windPoints[]; };
#else
layout(set = 0, binding = ARBOR_COMPUTE_VERTICES, std430) readonly buffer Vertices { TreeVertex vertices[]; };
#endif
// Per quad patch: offset of its points, four valences and four prefixes (8 bits each), kind (0 regular,
// 1 extraordinary, 2 fallback).
layout(set = 0, binding = ARBOR_COMPUTE_PATCHES, std430) readonly buffer Patches { uvec4 patches[]; };
layout(set = 0, binding = ARBOR_COMPUTE_POINTS, std430) readonly buffer Points { uint points[]; };
// Three vertex indices per triangle of the triangulated mesh (PN-triangles).
layout(set = 0, binding = ARBOR_COMPUTE_TRIANGLES, std430) readonly buffer Triangles { uint triangleIndices[]; };
layout(set = 0, binding = ARBOR_COMPUTE_CONTROL, std430) buffer Control { vec4 control[]; };
layout(set = 0, binding = ARBOR_COMPUTE_HULLS, std430) buffer Hulls { vec4 hulls[]; };
layout(set = 0, binding = ARBOR_COMPUTE_VISIBLE, std430) buffer Visible { uvec2 visible[]; };
// Per instance (ARBOR_COUNTERS): one counter per bucket, then the draw commands written for the corner
// pipeline and for the tessellated one.
layout(set = 0, binding = ARBOR_COMPUTE_COUNTS, std430) buffer Counts { uint counts[]; };
// VkDrawIndirectCommand: vertex count, instance count, first vertex, first instance.
layout(set = 0, binding = ARBOR_COMPUTE_COMMANDS, std430) buffer Commands { uvec4 commands[]; };

// Pass flags.
const uint kCullFrustum = 1u;   // drop patches whose hull lies outside the view
const uint kCullBackFaces = 2u; // drop patches whose every normal faces away from the eye
const uint kBuckets = 4u;       // sort by largest factor into ARBOR_BUCKETS buckets (else all in bucket 0)
const uint kZeroFill = 8u;      // pad the draw commands with empty ones (devices without drawIndirectCount)
const uint kTriangles = 16u;    // PN triangles (else ACC quads)
const uint kCornerBucket = 32u; // patches at factor 1 go to bucket 0, drawn without the tessellator

layout(push_constant) uniform Pass {
  mat4 model;           // the instance's object -> world
  uint primitiveCount;  // patches or triangles of the tree
  uint listBase;        // first entry of this instance's lists in Visible (bucket b at listBase + b * count)
  uint counterBase;     // first of this instance's ARBOR_COUNTERS counters
  uint commandBase;     // first of this instance's draw commands: one for bucket 0, then the tessellated
  uint flags;
  uint maxCommands;     // room for this instance's draw commands
  float windHeight;     // wind.comp: the tree's height (primitiveCount: its vertices)
  uint pad1;
  uvec4 perDrawLow;     // patches per draw in buckets 0-3 ...
  uvec4 perDrawHigh;    // ... and 4-7: what the device's vertex limit allows
} pass;

ARBOR_RUNTIME_OVER(counts.length())
