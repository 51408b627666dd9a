#version 450
#extension GL_GOOGLE_include_directive : require
// Wind on the control cage (docs/wind.md): each vertex of the rest cage moved by the wind into the posed cage,
// which the control-point passes then refine; vertices the faces share move once, so the surface stays closed.

#define ARBOR_POSES_VERTICES
#include "compute.glsl"
#include "wind.glsl"

layout(local_size_x = ARBOR_COMPUTE_GROUP) in;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pass.primitiveCount) return;
  TreeVertex v = rest[i];
  v.positionRadius.xyz += windOffset(v.positionRadius.xyz, windPoints[2u * i], windPoints[2u * i + 1u], pass.windHeight);
  vertices[i] = v;
}
