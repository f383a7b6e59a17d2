// With MSAA: the surfaces past the first that the pixels of a work group show,
// listed in shared memory and then shaded by the whole group, one an
// invocation (Lauritzen's reshuffle, as the deferred modes' compute lighting
// shares out edge samples): an edge pixel does not keep the other
// invocations of its warp waiting while it shades its second and third
// surface. Each entry: the pixel in the 8x8 group, its group's leader sample
// and the samples it shades. Needs visibility.glsl.
shared uint s_extra[64 * (kSamples - 1)];
shared uint s_extra_count;

// Empties the list: a barrier must come between this and the first add.
void clear_extra_surfaces() {
  if (gl_LocalInvocationIndex == 0u) s_extra_count = 0u;
}

// Lists the surface that `leader` leads in this invocation's pixel.
void add_extra_surface(int leader, uint group_of) {
  s_extra[atomicAdd(s_extra_count, 1u)] = gl_LocalInvocationIndex | uint(leader) << 6 | group_mask(group_of, leader) << 16;
}

// Entry `k` of the list (after a barrier): its pixel, leader and samples.
ivec2 extra_surface(uint k, ivec2 origin, out int leader, out uint samples) {
  uint entry = s_extra[k];
  leader = int((entry >> 6) & 0xfu);
  samples = entry >> 16;
  return origin + ivec2(entry & 7u, (entry >> 3) & 7u);
}
