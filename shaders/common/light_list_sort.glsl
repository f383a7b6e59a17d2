// The lists too long for one invocation to sort (light_list_sort.comp's LONG
// step): light_list_scan.comp appends each to u_long_bins and counts them in
// the indirect dispatch that sorts them. C++: LightIndexList.
const uint kShortList = 128u;
layout(std430, binding = 15) buffer LongBins {
  uvec3 u_long_groups;    // the LONG dispatch's size (glDispatchComputeIndirect): x at most 65,535
  uint u_long_bin_count;
  uint u_long_bins[];
};
