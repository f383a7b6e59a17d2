#version 450 core
// Reads each bin's light count (the assignment's count step), writes each
// bin's range of the light index array (exclusive prefix sums: bins follow
// each other) and turns the counts into the cursors a scatter's write step
// advances; also the longest list and the bins holding any light, and lists
// the bins too long for one invocation to sort (light_list_sort.comp).
// Bins number hundreds of thousands at fine grids (80x45x32 at 1080p is
// 115,200), so the scan is spread over the GPU in three steps (u_step), each
// work group taking a block of kScanBlock bins, 16 consecutive bins an
// invocation:
//   kScanReduce  each block's sum, longest list and filled bins;
//   kScanBlocks  one work group turns the blocks' sums into their offsets;
//   kScanWrite   each block scans itself from its offset and writes.
// One work group for everything, as this was, runs on one of an H200's 132
// SMs for a time that grows with the bins; the whole assignment there took
// 0.37 ms at 4,608 clusters, 0.75 at 115,200 and 1.48 at 261,120 with 1,024
// lights (docs/benchmarks.md). C++: LightIndexList.
layout(local_size_x = 256) in;

#include "common/light_lists.glsl"
#include "common/light_list_sort.glsl"
#include "common/group_scan.glsl"

layout(std430, binding = 7) buffer BinCounts { uint u_bin_counts[]; };
// Per block: its sum (kScanReduce), then its first entry (kScanBlocks).
layout(std430, binding = 22) buffer ScanBlocks { uint u_scan_blocks[]; };
uniform uint u_bins;
uniform uint u_step;

const uint kScanReduce = 0u, kScanBlocks = 1u, kScanWrite = 2u;
const uint kPerInvocation = 16u, kScanBlock = 256u * kPerInvocation;

shared uint s_longest, s_filled;

uint block_index() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

void reduce() {
  uint thread = gl_LocalInvocationIndex, first = block_index() * kScanBlock + thread * kPerInvocation;
  if (thread == 0u) {
    s_longest = 0u;
    s_filled = 0u;
  }
  uint sum = 0u, longest = 0u, filled = 0u;
  for (uint b = first; b < min(first + kPerInvocation, u_bins); ++b) {
    uint count = u_bin_counts[b];
    sum += count;
    longest = max(longest, count);
    filled += count > 0u ? 1u : 0u;
  }
  uint total;
  group_exclusive_sum(sum, total);
  if (longest > 0u) atomicMax(s_longest, longest);
  if (filled > 0u) atomicAdd(s_filled, filled);
  barrier();
  if (thread == 0u) {
    u_scan_blocks[block_index()] = total;
    if (s_longest > 0u) atomicMax(u_light_bin_max, s_longest);
    if (s_filled > 0u) atomicAdd(u_light_filled_bins, s_filled);
  }
}

// One work group; each invocation takes a run of consecutive blocks (one up
// to 256 blocks, 1,048,576 bins).
void scan_blocks() {
  uint thread = gl_LocalInvocationIndex, blocks = (u_bins + kScanBlock - 1u) / kScanBlock;
  uint per_thread = (blocks + 255u) / 256u;
  uint first = min(thread * per_thread, blocks), end = min(first + per_thread, blocks), sum = 0u;
  for (uint b = first; b < end; ++b) sum += u_scan_blocks[b];
  uint total;
  uint offset = group_exclusive_sum(sum, total);
  for (uint b = first; b < end; ++b) {
    uint block_sum = u_scan_blocks[b];
    u_scan_blocks[b] = offset;
    offset += block_sum;
  }
}

void write() {
  uint thread = gl_LocalInvocationIndex, first = block_index() * kScanBlock + thread * kPerInvocation;
  uint end = min(first + kPerInvocation, u_bins);
  uint counts[kPerInvocation], sum = 0u;
  for (uint k = 0u; k < kPerInvocation; ++k) {
    counts[k] = first + k < end ? u_bin_counts[first + k] : 0u;
    sum += counts[k];
  }
  uint total;
  uint offset = u_scan_blocks[block_index()] + group_exclusive_sum(sum, total);
  for (uint k = 0u; k < kPerInvocation; ++k) {
    uint b = first + k;
    if (b >= end) break;
    u_light_ranges[b] = LightRange(offset, counts[k]);
    u_bin_counts[b] = offset;
    if (counts[k] > kShortList) {
      // The sort's dispatch is as large as the list: the largest slot taken plus one.
      uint slot = atomicAdd(u_long_bin_count, 1u);
      u_long_bins[slot] = b;
      atomicMax(u_long_groups.x, min(slot + 1u, 65535u));
    }
    offset += counts[k];
  }
}

void main() {
  if (u_step == kScanReduce) reduce();
  else if (u_step == kScanBlocks) scan_blocks();
  else write();
}
