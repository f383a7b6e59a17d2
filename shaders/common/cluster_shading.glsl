// Shading with a cluster's lights only: shared by clustered forward+ and
// clustered deferred.
#include "shading.glsl"
#include "clusters.glsl"

// The sum of the lights in the cluster of `s` (the unlit terms are the caller's).
LightSum shade_cluster_lights(Surface s, vec2 frag_coord) {
  float view_depth = -(u_view * vec4(s.position, 1.0)).z;
  LightRange range = u_light_ranges[cluster_index(frag_coord, u_viewport_size, view_depth)];
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  uint end = min(range.offset + range.count, u_list_info.x);
  for (uint i = range.offset; i < end; ++i) add_light(sum, s, v, u_lights[u_light_indices[i]]);
  return sum;
}
