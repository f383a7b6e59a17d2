#version 450 core
// The visibility buffer's resolve for one material (u_material, its textures
// bound at units 0-4): one work group per tile that holds it (the
// classification's list, dispatched indirectly). Each of its pixels rebuilds
// its surface from the triangle it shows, evaluates the material with explicit
// gradients and shades it with its cluster's lights, storing the lit result
// (common/lighting_targets.glsl) once: no G-buffer between geometry and light.
// With MSAA each surface a pixel's samples show is shaded once, at the pixel
// centre as a raster pass shades it, and stored to the samples that show it:
// a pixel inside a triangle costs one shading, and so does one that two
// triangles of a flat or smooth surface share (surface_groups in
// visibility.glsl); silhouettes, creases and material seams cost one each.
#define COMPUTE_STAGE
#define EXPLICIT_GRADIENTS
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/material.glsl"
#include "common/cluster_shading.glsl"
#include "common/lighting_targets.glsl"
#include "visibility/visibility.glsl"
#include "visibility/material_tiles.glsl"

uniform uint u_material;

// Shades the triangle `id` names where `pixel` shows it, if its material is
// u_material, storing to the samples lighting_targets.glsl is told.
void shade_triangle(ivec2 pixel, uint id) {
  uint triangle;
  Instance instance = visible_instance(id, triangle);
  if (instance.material.x != u_material) return;
  VisibleSurface v = visible_surface(pixel, instance, triangle);
  Surface s = evaluate_material(v.material, v.flags, v.position, v.normal, v.tangent, v.uv, v.color, v.front_facing);
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), shade_cluster_lights(s, vec2(pixel) + 0.5));
}

void main() {
  uint tile = u_tiles[u_material * u_tile_capacity + gl_WorkGroupID.x];
  // Its work group is classify.comp's: one group a tile.
  ivec2 pixel = ivec2(tile & 0xffffu, tile >> 16) * ivec2(gl_WorkGroupSize.xy) + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  g_shaded_pixel = pixel;
#ifdef MSAA_SAMPLES
  // Each surface the samples show once, for every sample that shows it.
  uint ids[kSamples], group_id[kSamples], group_mask[kSamples];
  for (int i = 0; i < kSamples; ++i) ids[i] = fetch_sample(u_visibility, pixel, i).r;
  int groups = surface_groups(pixel, ids, u_material, group_id, group_mask);
  for (int g = 0; g < groups; ++g) {
    g_shaded_samples = group_mask[g];
    shade_triangle(pixel, group_id[g]);
  }
#else
  // A loop of one sample measured 10-15% slower on llvmpipe: the pixel's one identifier, straight.
  uint id = texelFetch(u_visibility, pixel, 0).r;
  if (id != 0u) shade_triangle(pixel, id);
#endif
}
