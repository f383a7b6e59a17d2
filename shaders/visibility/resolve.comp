#version 450 core
// The visibility buffer's resolve: each of its pixels rebuilds its surface
// from the triangle it shows, evaluates the material with explicit gradients
// and shades it with its cluster's lights, storing the lit result
// (common/lighting_targets.glsl) once: no G-buffer between geometry and light.
// Bound (the default variant): one dispatch per material (u_material, its
// textures bound at units 0-4), one work group per tile of its list
// (material_tiles.glsl). BINDLESS_TEXTURES: one dispatch, one work group per tile of
// the frame, which gives the background to empty samples (the classification's
// job otherwise) and evaluates the materials its tile shows one after the
// other, each sampled by handle: the loop keeps the handle dynamically
// uniform, as ARB_bindless_texture asks; each pixel is lit after the loop,
// once. With MSAA each surface a pixel's samples show is shaded once, at the
// pixel centre as a raster pass shades it, and stored to the samples that
// show it (surface_groups in visibility.glsl): the first by the pixel's own
// invocation, the others shared out over the work group
// (extra_surfaces.glsl); bindless, each a loop over the materials and one
// light loop.
#ifdef BINDLESS_TEXTURES
#extension GL_ARB_bindless_texture : require
#endif
#define COMPUTE_STAGE
#define EXPLICIT_GRADIENTS
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/frame.glsl"
#include "common/material.glsl"
#include "common/cluster_shading.glsl"
#include "common/lighting_targets.glsl"
#include "visibility/visibility.glsl"
#ifdef MSAA_SAMPLES
#include "visibility/extra_surfaces.glsl"
#endif

Surface material_surface(VisibleSurface v, uint material) {
  return evaluate_material(material, v.flags, v.position, v.normal, v.tangent, v.uv, v.color, v.front_facing);
}

// Lights `s` where `pixel` shows it, storing to the samples lighting_targets.glsl is told.
void light(ivec2 pixel, Surface s) {
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), shade_cluster_lights(s, vec2(pixel) + 0.5));
}

// Shades `triangle` of `instance` (whose material is `material`) where `pixel` shows it.
void shade(ivec2 pixel, Instance instance, uint triangle, uint material) {
  light(pixel, material_surface(visible_surface(pixel, instance, triangle), material));
}

#ifdef BINDLESS_TEXTURES
#include "visibility/tile_materials.glsl"

// Each surface's material takes a slot (kNone: none there); then the tile's
// distinct materials, so that the loop over them is the same for every invocation.
shared uint s_materials[64 * kSamples];
shared uint s_material_count;

// The material of `visible`, evaluated in its turn of the loop over the
// tile's `count` materials (its surface is undefined where `material` is
// kNone). Every invocation that runs the loop reads the same material from
// shared memory in a turn: the handles stay dynamically uniform.
Surface material_in_its_turn(VisibleSurface visible, uint material, uint count) {
  Surface surface;
  for (uint k = 0u; k < count; ++k) {
    uint m = s_materials[k];
    if (material == m) surface = material_surface(visible, m);
  }
  return surface;
}

#ifdef MSAA_SAMPLES
// Shades the triangle `id` names where `pixel` shows it, its `material`
// evaluated in its turn of the tile's `count`. The instance is looked up
// again, not kept from the grouping: kSamples instance records (36 words
// each) held across the barriers would cost registers in every invocation,
// and the second lookup (a binary search over the units, one record) reads
// what the first brought into the cache.
void shade_in_its_turn(ivec2 pixel, uint id, uint material, uint count) {
  uint triangle;
  Instance instance = visible_instance(id, triangle);
  light(pixel, material_in_its_turn(visible_surface(pixel, instance, triangle), material, count));
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(pixel, ivec2(u_viewport_size)));
  g_shaded_pixel = pixel;
  if (gl_LocalInvocationIndex == 0u) s_material_count = 0u;
#ifdef MSAA_SAMPLES
  clear_extra_surfaces();
#endif
  uint first = gl_LocalInvocationIndex * uint(kSamples);
  uint background = 0u;  // the samples without geometry, a bit each
#ifdef MSAA_SAMPLES
  uint ids[kSamples], group_of = 0xffffffffu, leaders = 0u;
  if (inside) {
    for (int i = 0; i < kSamples; ++i) {
      ids[i] = fetch_sample(u_visibility, pixel, i).r;
      if (ids[i] == 0u) background |= 1u << i;
    }
    leaders = surface_groups(pixel, ids, kAnyMaterial, group_of);
  }
  // A group's material at its leader's slot.
  for (int i = 0; i < kSamples; ++i) s_slot_material[first + uint(i)] = kNone;
  for (uint rest = leaders; rest != 0u; rest &= rest - 1u) {
    int leader = findLSB(rest);
    uint triangle;
    s_slot_material[first + uint(leader)] = visible_instance(id_at(ids, leader), triangle).material.x;
  }
  g_shaded_samples = background;
#else
  uint id = inside ? texelFetch(u_visibility, pixel, 0).r : 0u;
  if (inside && id == 0u) background = 1u;
  uint material = kNone;
  // The surface before its material: what the triangle gives does not depend on it.
  VisibleSurface visible;
  if (id != 0u) {
    uint triangle;
    Instance instance = visible_instance(id, triangle);
    material = instance.material.x;
    visible = visible_surface(pixel, instance, triangle);
  }
  s_slot_material[first] = material;
#endif
  if (background != 0u) write_background();
  barrier();
  // The first slot of the tile to hold a material lists it.
  for (int i = 0; i < kSamples; ++i) {
    if (first_slot_of_its_material(first + uint(i))) s_materials[atomicAdd(s_material_count, 1u)] = s_slot_material[first + uint(i)];
  }
#ifdef MSAA_SAMPLES
  add_extra_surfaces(leaders, group_of);
#endif
  barrier();
  uint count = s_material_count;
#ifdef MSAA_SAMPLES
  // The pixel's first surface here, the others shared out over the group
  // (extra_surfaces.glsl): each rebuilt once, its material evaluated in the
  // material's turn, lit after the turns. The light loop runs once a surface,
  // not once per material and surface.
  ivec2 origin = ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy);
  SurfaceWalk walk = walk_surfaces(leaders);
  uint id;
  int leader;
  while (next_surface(walk, ids, leaders, group_of, origin, id, leader)) {
    ivec2 local = g_shaded_pixel - origin;
    uint material = s_slot_material[uint(local.y * int(gl_WorkGroupSize.x) + local.x) * uint(kSamples) + uint(leader)];
    shade_in_its_turn(g_shaded_pixel, id, material, count);
  }
#else
  Surface surface = material_in_its_turn(visible, material, count);
  // Lit once, after every material: a tile that shows several runs the light
  // loop (the resolve's longest part) once, not once per material.
  if (material != kNone) light(pixel, surface);
#endif
}
#else
#include "visibility/material_tiles.glsl"

uniform uint u_material;

// Shades the triangle `id` names where `pixel` shows it, if its material is u_material.
void shade_triangle(ivec2 pixel, uint id) {
  uint triangle;
  Instance instance = visible_instance(id, triangle);
  if (instance.material.x == u_material) shade(pixel, instance, triangle, u_material);
}

void main() {
  // The material's dispatch folds its range into rows (material_lists.comp);
  // a group past its end takes a tile outside the image, and the one bounds
  // test below ends it (a second early return, with a division by the tiles
  // per row, measured 15-20% slower on llvmpipe at 1,024 lights).
  uint index = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint tile = index < u_material_tiles[u_material].tile_count ? u_tiles[u_material_tiles[u_material].first_tile + index] : kNoTile;
  // Its work group is classify.comp's: one group a tile.
  ivec2 origin = ivec2(tile & 0xffffu, tile >> 16) * ivec2(gl_WorkGroupSize.xy);
  ivec2 pixel = origin + ivec2(gl_LocalInvocationID.xy);
  bool inside = all(lessThan(pixel, ivec2(u_viewport_size)));
  g_shaded_pixel = pixel;
#ifdef MSAA_SAMPLES
  // Every invocation reaches the barriers (no early return): the pixel's first
  // surface of this material here, the others shared out over the group.
  clear_extra_surfaces();
  barrier();
  uint ids[kSamples], group_of = 0xffffffffu, leaders = 0u;
  if (inside) {
    for (int i = 0; i < kSamples; ++i) ids[i] = fetch_sample(u_visibility, pixel, i).r;
    leaders = surface_groups(pixel, ids, u_material, group_of);
  }
  add_extra_surfaces(leaders, group_of);
  barrier();
  // The pixel's first surface, then the list's.
  SurfaceWalk walk = walk_surfaces(leaders);
  uint id;
  int leader;
  while (next_surface(walk, ids, leaders, group_of, origin, id, leader)) shade_triangle(g_shaded_pixel, id);
#else
  if (!inside) return;
  // A loop of one sample measured 10-15% slower on llvmpipe: the pixel's one identifier, straight.
  uint id = texelFetch(u_visibility, pixel, 0).r;
  if (id != 0u) shade_triangle(pixel, id);
#endif
}
#endif
