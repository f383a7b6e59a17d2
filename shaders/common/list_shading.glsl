// Shading with one bin's light list (a tile's or a cluster's): shared by the
// tiled and clustered modes' lighting passes and their forward passes over
// blended surfaces. The lists hold the shadowed lights first (clusters keep
// light order, and the ShadowAtlas moved those to the front; tiled/assign.comp
// writes them first), so one loop looks their maps up and one does not
// (common/shading.glsl says why).
#include "shading.glsl"
#include "light_lists.glsl"

// The sum of the lights in `range` (the unlit terms are the caller's). A
// range that ends past the list's `capacity` did not fit this frame (the list
// grows for the next one, LightIndexList): its pixels add every light that
// reaches them instead, the same sum, only slower.
LightSum shade_listed_lights(Surface s, LightRange range, uint capacity) {
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  if (range.count > capacity || range.offset > capacity - range.count) {
    add_buffer_lights_culled(sum, s, v, true);
    return sum;
  }
  uint end = range.offset + range.count;
  uint i = range.offset;
  for (; i < end && has_shadow_maps(u_lights[u_light_indices[i]]); ++i) add_light_as(sum, s, v, u_lights[u_light_indices[i]], true);
  for (; i < end; ++i) add_light_as(sum, s, v, u_lights[u_light_indices[i]], false);
  return sum;
}
