// An exclusive prefix sum over a work group of 256 invocations
// (local_size_x = 256), for the scans that turn counts into ranges: the light
// lists' (common/light_list_scan.comp) and the visibility buffer's material
// tile lists' (visibility/material_lists.comp).

shared uint s_scan_sums[256];
shared uint s_scan_total;

// Each invocation's `value` summed over the invocations before it; `total` is
// the group's sum. One invocation walks the 256 partial sums: two barriers,
// where a tree takes sixteen: a software renderer's barriers cost more than
// the walk (on llvmpipe the tree scanned 261,120 bins in 9.6-14.6 ms, this in
// 3.3-5.2 against the single group's 2.1-4.0), while on a GPU each block's
// walk runs beside the others'.
uint group_exclusive_sum(uint value, out uint total) {
  uint thread = gl_LocalInvocationIndex;
  s_scan_sums[thread] = value;
  barrier();
  if (thread == 0u) {
    uint running = 0u;
    for (uint t = 0u; t < 256u; ++t) {
      uint part = s_scan_sums[t];
      s_scan_sums[t] = running;
      running += part;
    }
    s_scan_total = running;
  }
  barrier();
  total = s_scan_total;
  uint exclusive = s_scan_sums[thread];
  barrier();  // s_scan_sums is free again for a later call
  return exclusive;
}
