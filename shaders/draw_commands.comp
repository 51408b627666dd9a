#version 450
#extension GL_GOOGLE_include_directive : require
// After culling, per instance: one indirect draw per run of at most perDraw(b) patches of bucket b (the most
// the device's vertex limit allows for that bucket's factors), written back to back; their number follows the
// bucket counters, for vkCmdDrawIndirectCount.

layout(local_size_x = 1) in;

#include "compute.glsl"

uint perDraw(uint bucket) { return bucket < 4u ? pass.perDrawLow[bucket] : pass.perDrawHigh[bucket - 4u]; }

void main() {
  uint written = 0u;
  for (uint bucket = 0u; bucket < uint(ARBOR_BUCKETS); ++bucket) {
    uint count = counts[pass.counterBase + bucket], size = max(perDraw(bucket), 1u);
    uint first = pass.listBase + bucket * pass.primitiveCount;
    for (uint done = 0u; done < count && written < pass.maxCommands; done += size) {
      commands[pass.commandBase + written] = uvec4(min(size, count - done), 1u, first + done, 0u);
      ++written;
    }
  }
  counts[pass.counterBase + uint(ARBOR_BUCKETS)] = written;
  if ((pass.flags & kZeroFill) != 0u) {
    for (uint i = written; i < pass.maxCommands; ++i) commands[pass.commandBase + i] = uvec4(0u);
  }
}
