#version 450
#extension GL_GOOGLE_include_directive : require
// Fake branches (Nystad 5.5.4): each skeleton edge becomes a card facing the eye, as wide as the branch,
// that the fragment stage shades as the cylinder it stands for.

#include "scene.glsl"
#include "wind.glsl"
#include "card.glsl"

layout(location = 0) out vec2 acrossAndV;       // x: -1 .. 1 across the rectangle, y: bark texture v
layout(location = 1) flat out vec3 sideways;    // unit vector across the rectangle
layout(location = 2) flat out vec3 facing;      // unit vector from the axis towards the eye

void main() {
  uint index = cardIndex();
  Impostor segment = impostors[index];
  vec3 from = segment.fromRadius.xyz, to = segment.toRadius.xyz;
  if (kWind && draw.windHeight > 0.0) {  // both ends move with their skeleton nodes
    uint w = draw.impostorWindBase + 2u * ARBOR_WIND_VEC4S * index;
    from += windOffset(from, windPoints[w], windPoints[w + 1u], draw.windHeight);
    to += windOffset(to, windPoints[w + 2u], windPoints[w + 3u], draw.windHeight);
  }
  vec3 a = (draw.model * vec4(from, 1.0)).xyz;
  vec3 b = (draw.model * vec4(to, 1.0)).xyz;
  float length_ = length(b - a);
  vec3 axis = length_ > 1e-9 ? (b - a) / length_ : vec3(0.0, 0.0, 1.0);
  vec3 toEye = scene.cameraPos.xyz - 0.5 * (a + b);
  vec3 side = cross(axis, toEye);
  // Seen end-on the card has no preferred side; any perpendicular keeps the count of quads exact.
  if (dot(side, side) <= 1e-12 * max(dot(toEye, toEye), 1e-12)) side = cross(axis, abs(axis.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0));
  side = normalize(side);
  vec3 front = cross(side, axis);  // (axis x e) x axis: the eye direction without its part along the axis
  // Each end reaches on by half its radius, so consecutive segments overlap where the stem bends.
  uint corner = cardCorner();
  bool atEnd = (corner & 2u) != 0u;
  float r = atEnd ? segment.toRadius.w : segment.fromRadius.w;
  vec3 end = atEnd ? b + axis * (0.5 * r) : a - axis * (0.5 * r);
  float s = (corner & 1u) != 0u ? 1.0 : -1.0;
  vec3 worldPosition = end + side * (r * s);
  acrossAndV = vec2(s, atEnd ? segment.barkV.y : segment.barkV.x);
  sideways = side;
  facing = front;
  gl_Position = scene.viewProj * vec4(worldPosition, 1.0);
}
