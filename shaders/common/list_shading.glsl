// Shading with one bin's light list (a tile's or a cluster's): shared by the
// tiled and clustered modes' lighting passes and their forward passes over
// blended surfaces. The lists keep light order, and the ShadowAtlas moved the
// shadowed lights to the front, so one loop looks their maps up and one does
// not (common/shading.glsl says why).
#include "shading.glsl"
#include "light_lists.glsl"

// The sum of the lights in `range` (the unlit terms are the caller's), and of
// the lights that did not fit this frame's lists (LightIndexList: almost
// always none), each where it reaches: the same sum, only slower.
LightSum shade_listed_lights(Surface s, LightRange range) {
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  uint end = range.offset + range.count;
  uint i = range.offset;
  for (; i < end && has_shadow_maps(light_at(light_index(i))); ++i) add_light_as(sum, s, v, light_at(light_index(i)), true);
  for (; i < end; ++i) add_light_as(sum, s, v, light_at(light_index(i)), false);
  for (uint o = 0u; o < overflow_count(); ++o) {
    Light light = light_at(overflow_light(o));
    if (light_reaches(light, s.position)) add_light(sum, s, v, light);
  }
  return sum;
}
