#version 450
#extension GL_GOOGLE_include_directive : require
// After culling, per instance: bucket 0 (every factor 1) as one draw of the corner pipeline, then one indirect
// draw per run of at most perDraw(b) patches of bucket b >= 1 (the most the device's vertex limit allows for
// that bucket's factors), written back to back; their numbers go to the instance's last two counters, for
// vkCmdDrawIndirectCount.

#include "compute.glsl"

layout(local_size_x = 1) in;

uint perDraw(uint bucket) { return bucket < 4u ? pass.perDrawLow[bucket] : pass.perDrawHigh[bucket - 4u]; }

void main() {
  uint flags = runtime(pass.flags), room = runtime(pass.maxCommands);
  uint corners = counts[pass.counterBase];
  uint cornerVertices = (flags & kTriangles) != 0u ? 3u : 6u;  // a triangle, or a quad's two
  commands[pass.commandBase] = uvec4(corners * cornerVertices, 1u, pass.listBase * cornerVertices, 0u);
  counts[pass.counterBase + uint(ARBOR_BUCKETS)] = corners > 0u ? 1u : 0u;
  uint first = pass.commandBase + 1u, written = 0u;
  for (uint bucket = 1u; bucket < uint(ARBOR_BUCKETS); ++bucket) {
    uint count = counts[pass.counterBase + bucket], size = max(perDraw(bucket), 1u);
    uint list = pass.listBase + bucket * pass.primitiveCount;
    for (uint done = 0u; done < count && written < room; done += size) {
      commands[first + written] = uvec4(min(size, count - done), 1u, list + done, 0u);
      ++written;
    }
  }
  counts[pass.counterBase + uint(ARBOR_BUCKETS) + 1u] = written;
  if ((flags & kZeroFill) != 0u) {
    for (uint i = written; i < room; ++i) commands[first + i] = uvec4(0u);
  }
}
