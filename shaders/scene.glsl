// Shared by every stage: the scene uniforms, the tree's buffers and its textures (set 0).

layout(set = 0, binding = 0, std140) uniform Scene {
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
  uvec4 flags;        // x: capture evaluated points, y: wireframe colouring, z: back faces in magenta
  vec4 lens;          // x: pixels covered by one unit of length at unit distance
  vec4 leafLod;       // distance (m) up to which all leaves show (0: no thinning), density, unused, shadow leaves
} scene;

struct TreeVertex {
  vec4 positionRadius;  // object space, branch radius
  vec4 normalLevel;     // unit normal, stem level
  vec4 uvw;             // u mirrored front to back, v along the branch, w the flip coordinate
};

layout(set = 0, binding = 1, std430) readonly buffer Vertices { TreeVertex vertices[]; };
// Per patch: offset of its points, four valences and four prefixes (8 bits each), kind (0 regular,
// 1 extraordinary, 2 fallback).
layout(set = 0, binding = 2, std430) readonly buffer Patches { uvec4 patches[]; };
layout(set = 0, binding = 3, std430) readonly buffer Points { uint points[]; };
// Three vertex indices per triangle of the triangulated mesh (PN-triangles).
layout(set = 0, binding = 7, std430) readonly buffer Triangles { uint triangleIndices[]; };

struct Leaf {
  vec4 positionLength;  // object space base of the blade, its length
  vec4 directionWidth;  // unit vector base -> tip, half width
  vec4 normalKind;      // blade normal, kind (atlas cell)
};
// In a random order, so that the first ones are a fair sample (thinning, self-shadowing).
layout(set = 0, binding = 8, std430) readonly buffer Leaves { Leaf leaves[]; };
layout(set = 0, binding = 9) uniform sampler2D leafAtlas;

struct Impostor {
  vec4 fromRadius;  // object space parent node, the edge's radius leaving it
  vec4 toRadius;    // the node, the radius arriving there
  vec4 barkV;       // texture v at both ends, stem level
};
// Fake branches: the skeleton edges of the stems the mesh leaves out.
layout(set = 0, binding = 10, std430) readonly buffer Impostors { Impostor impostors[]; };
layout(set = 0, binding = 4) uniform sampler2D barkColor;
layout(set = 0, binding = 5) uniform sampler2D barkHeight;

layout(push_constant) uniform Draw {
  mat4 model;
  uint patchBase;  // first patch of this draw: gl_PrimitiveID restarts at 0 for every draw
  uint leafCount;  // this tree's leaves (trees of a forest differ)
} draw;

const float PI = 3.14159265358979;

// Where a point lands on the screen, in pixels (for tessellation factors).
vec2 toPixels(vec3 objectPosition) {
  vec4 clip = scene.viewProj * (draw.model * vec4(objectPosition, 1.0));
  clip.w = max(clip.w, 1e-4);
  return (clip.xy / clip.w * 0.5 + 0.5) * scene.viewport.xy;
}

// Tessellation factor of an edge from its two end points only, so the patches on both sides agree (no cracks).
float edgeFactor(vec3 a, vec3 b) {
  if (scene.tess.y <= 0.0) return scene.tess.x;
  vec4 ca = scene.viewProj * (draw.model * vec4(a, 1.0));
  vec4 cb = scene.viewProj * (draw.model * vec4(b, 1.0));
  if (ca.w <= 1e-3 || cb.w <= 1e-3) return scene.tess.z;  // crosses the eye plane: as fine as allowed
  float pixels = length((ca.xy / ca.w - cb.xy / cb.w) * 0.5 * scene.viewport.xy);
  return clamp(pixels / scene.tess.y, 1.0, scene.tess.z);
}

// A box of points entirely outside one clip plane is not drawn.
bool outsideFrustum(vec3 lo, vec3 hi) {
  vec4 c[8];
  for (int i = 0; i < 8; ++i) {
    vec3 p = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y, (i & 4) != 0 ? hi.z : lo.z);
    c[i] = scene.viewProj * (draw.model * vec4(p, 1.0));
  }
  for (int axis = 0; axis < 3; ++axis) {
    bool allBelow = true, allAbove = true;
    for (int i = 0; i < 8; ++i) {
      // Vulkan clip space: -w < x, y < w and 0 < z < w.
      allBelow = allBelow && c[i][axis] < (axis == 2 ? 0.0 : -c[i].w);
      allAbove = allAbove && c[i][axis] > c[i].w;
    }
    if (allAbove || allBelow) return true;
  }
  return false;
}
