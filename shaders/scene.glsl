// Shared by every stage: the scene uniforms, the tree's buffers and its textures (set 0).

#include "scene_uniforms.glsl"

// Control points built once per mesh (acc_control.comp, pn_control.comp): ARBOR_ACC_CONTROL_VEC4S per quad
// patch, or ARBOR_PN_CONTROL_VEC4S per triangle, in the layout interface.h gives.
layout(set = 0, binding = ARBOR_BINDING_CONTROL, std430) readonly buffer Control { vec4 control[]; };
// This frame's surviving patches (patch_cull.comp): the patch and its outer factors, 8 bits each.
layout(set = 0, binding = ARBOR_BINDING_VISIBLE, std430) readonly buffer Visible { uvec2 visible[]; };

struct Leaf {
  vec4 positionLength;  // object space base of the blade, its length
  vec4 directionWidth;  // unit vector base -> tip, half width
  vec4 normalKind;      // blade normal, kind (atlas cell)
};
// In a random order, so that the first ones are a fair sample (thinning, self-shadowing).
layout(set = 0, binding = ARBOR_BINDING_LEAVES, std430) readonly buffer Leaves { Leaf leaves[]; };
layout(set = 0, binding = ARBOR_BINDING_LEAF_ATLAS) uniform sampler2D leafAtlas;

struct Impostor {
  vec4 fromRadius;  // object space parent node, the edge's radius leaving it
  vec4 toRadius;    // the node, the radius arriving there
  vec4 barkV;       // texture v at both ends, stem level
};
// Fake branches: the skeleton edges of the stems the mesh leaves out.
layout(set = 0, binding = ARBOR_BINDING_IMPOSTORS, std430) readonly buffer Impostors { Impostor impostors[]; };
layout(set = 0, binding = ARBOR_BINDING_BARK_COLOR) uniform sampler2D barkColor;    // alpha: the height (fragment stages)
layout(set = 0, binding = ARBOR_BINDING_BARK_HEIGHT) uniform sampler2D barkHeight;  // displacement (vertex and evaluation stages)

// Wind records (interface.h): per mesh vertex, then per leaf from draw.leafWindBase, per fake-branch end from
// draw.impostorWindBase.
layout(set = 0, binding = ARBOR_BINDING_WIND, std430) readonly buffer Wind { vec4 windPoints[]; };

layout(push_constant) uniform Draw {
  mat4 model;
  uint leafCount;         // this tree's leaves (trees of a forest differ)
  float windHeight;       // the tree's height for the trunk's bend (0: this tree has no wind records)
  uint leafWindBase;      // first vec4 of the leaves' wind records
  uint impostorWindBase;  // first vec4 of the fake-branch ends' records
} draw;

ARBOR_RUNTIME_OVER(control.length())
