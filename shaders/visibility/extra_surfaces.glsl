// With MSAA: the surfaces past the first that the pixels of a work group show,
// listed in shared memory and then shaded by the whole group, one an
// invocation (Lauritzen's reshuffle, as the deferred modes' compute lighting
// shares out edge samples): an edge pixel does not keep the other
// invocations of its warp waiting while it shades its second and third
// surface. Each entry: the pixel in the 8x8 group, its group's leader sample
// and the samples it shades. Needs visibility.glsl and lighting_targets.glsl.
shared uint s_extra[64 * (kSamples - 1)];
shared uint s_extra_count;

// Empties the list: a barrier must come between this and the first add.
void clear_extra_surfaces() {
  if (gl_LocalInvocationIndex == 0u) s_extra_count = 0u;
}

// Lists the surfaces past the first that this invocation's pixel shows
// (`leaders`, a bit per group's leader sample; surface_groups in visibility.glsl).
void add_extra_surfaces(uint leaders, uint group_of) {
  for (uint rest = leaders & (leaders - 1u); rest != 0u; rest &= rest - 1u) {
    int leader = findLSB(rest);
    s_extra[atomicAdd(s_extra_count, 1u)] = gl_LocalInvocationIndex | uint(leader) << 6 | group_mask(group_of, leader) << 16;
  }
}

// The surfaces one invocation shades, after the barrier that ends the adds:
// its pixel's first, then every 64th entry of the list from its own index.
// One loop over both (while (next_surface(walk, ...))), so that the shading
// in its body is compiled once: two calls inlined it twice, and zink took
// 75 s instead of 45 to compile the bindless resolve.
struct SurfaceWalk {
  bool own;  // the pixel's first surface is still to come
  uint entry;
};

SurfaceWalk walk_surfaces(uint leaders) {
  return SurfaceWalk(leaders != 0u, gl_LocalInvocationIndex);
}

// Steps to the next surface: points g_shaded_pixel and g_shaded_samples
// (lighting_targets.glsl) at it and gives its identifier and group's leader
// sample; false when there is none.
bool next_surface(inout SurfaceWalk walk, uint ids[kSamples], uint leaders, uint group_of, ivec2 origin,
                  out uint id, out int leader) {
  if (walk.own) {
    walk.own = false;
    leader = findLSB(leaders);
    g_shaded_samples = group_mask(group_of, leader);
    id = id_at(ids, leader);
    return true;
  }
  if (walk.entry >= s_extra_count) return false;
  uint entry = s_extra[walk.entry];
  walk.entry += gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  leader = int((entry >> 6) & 0xfu);
  g_shaded_samples = entry >> 16;
  g_shaded_pixel = origin + ivec2(entry & 7u, (entry >> 3) & 7u);
  id = fetch_sample(u_visibility, g_shaded_pixel, leader).r;
  return true;
}
