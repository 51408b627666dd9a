// The interface between C++ and the shaders: descriptor bindings, buffer record sizes, push-constant sizes and
// tessellation buckets. Included by GLSL (#include "interface.h") and by C++ (engine/render), which
// static_asserts its structs against the sizes here, so the two sides cannot drift apart silently.
#ifndef ARBOR_SHADER_INTERFACE_H
#define ARBOR_SHADER_INTERFACE_H

// Graphics set 0 (scene.glsl).
#define ARBOR_BINDING_SCENE 0
#define ARBOR_BINDING_VERTICES 1
#define ARBOR_BINDING_PATCHES 2
#define ARBOR_BINDING_POINTS 3
#define ARBOR_BINDING_BARK_COLOR 4
#define ARBOR_BINDING_BARK_HEIGHT 5
#define ARBOR_BINDING_CAPTURE 6
#define ARBOR_BINDING_TRIANGLES 7
#define ARBOR_BINDING_LEAVES 8
#define ARBOR_BINDING_LEAF_ATLAS 9
#define ARBOR_BINDING_IMPOSTORS 10
#define ARBOR_BINDING_CONTROL 11  // control points built once per mesh (acc_control.comp, pn_control.comp)
#define ARBOR_BINDING_VISIBLE 12  // this frame's surviving patches with their factors (patch_cull.comp)
#define ARBOR_BINDING_WIND 13     // per vertex, leaf and fake-branch end: what moves it in the wind (wind.glsl)
#define ARBOR_GRAPHICS_BINDINGS 14

// Compute set 0 (compute.glsl), shared by the control-point, culling and draw-command passes.
#define ARBOR_COMPUTE_SCENE 0
#define ARBOR_COMPUTE_VERTICES 1
#define ARBOR_COMPUTE_PATCHES 2
#define ARBOR_COMPUTE_POINTS 3
#define ARBOR_COMPUTE_TRIANGLES 4
#define ARBOR_COMPUTE_CONTROL 5
#define ARBOR_COMPUTE_HULLS 6
#define ARBOR_COMPUTE_VISIBLE 7
#define ARBOR_COMPUTE_COUNTS 8
#define ARBOR_COMPUTE_COMMANDS 9
#define ARBOR_COMPUTE_REST 10     // the cage at rest, which wind.comp poses into the Vertices binding
#define ARBOR_COMPUTE_WIND 11
#define ARBOR_COMPUTE_BINDINGS 12
#define ARBOR_COMPUTE_GROUP 64  // invocations per workgroup of the per-patch passes

// Control records, in vec4s per primitive.
// ACC quad: 16 Bezier points (xyz, radius), their 16 (u, v, w, 0), 4 corner limit normals (zero for a fallback
// patch), 4 corner (u, v, w) of the cage.
#define ARBOR_ACC_CONTROL_VEC4S 40
// PN triangle: 3 corners (xyz, radius), 7 cubic points b210 b120 b021 b012 b102 b201 b111, 3 corner normals,
// 3 quadratic normals n110 n011 n101, 3 corner (u, v, w, 0).
#define ARBOR_PN_CONTROL_VEC4S 19
// Per primitive, for culling: (box low, displacement reach), (box high, 0), (normal cone axis, sine of its
// half angle; > 1 when the cone is too wide to cull anything).
#define ARBOR_HULL_VEC4S 3

// Wind records: two vec4 per point (reach on branch levels 1, 2, 3+, w: the tree's phase in the gusts; their
// stems' phases, w: a leaf's flutter phase): the mesh's vertices, then the leaves (in the leaf buffer's order), then two per fake-branch segment.
#define ARBOR_WIND_VEC4S 2
// Tessellation buckets: bucket b holds the patches whose largest factor is in (2^(b-1), 2^b], so that each
// draw can be sized for the vertices its own patches make. Bucket 0 (every factor 1) is drawn without the
// tessellator where the frame allows it; unbucketed frames put every other patch in bucket 1.
#define ARBOR_BUCKETS 7
// Per instance: a counter per bucket, then the draws without and with the tessellator.
#define ARBOR_COUNTERS (ARBOR_BUCKETS + 2)

// Push constants in bytes: DrawConstants (graphics) and PassConstants (compute).
#define ARBOR_DRAW_CONSTANTS_BYTES 80
#define ARBOR_PASS_CONSTANTS_BYTES 128

// Specialization constants (bools) of the tree's and the cards' vertex and evaluation stages: lavapipe runs both sides of a
// branch on a uniform, so what is off costs as much as what is on unless a pipeline variant compiles it out.
#define ARBOR_SPEC_DISPLACED 0  // displacement along the normal (bark.glsl)
#define ARBOR_SPEC_CAPTURE 1    // ACC's evaluation stage writes its points to the capture buffer (tests)
#define ARBOR_SPEC_WIND 2       // the flat mesh's, leaves' and fake branches' vertex stages move with the wind (wind.glsl)

// Bytes of one VkDrawIndirectCommand.
#define ARBOR_DRAW_COMMAND_BYTES 16

#endif
