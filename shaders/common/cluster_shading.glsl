// Shading with a cluster's lights only: shared by clustered forward+ and
// clustered deferred.
#include "shading.glsl"
#include "clusters.glsl"

vec3 shade_cluster_lights(Surface s, vec2 frag_coord) {
  float view_depth = -(u_view * vec4(s.position, 1.0)).z;
  LightRange range = u_light_ranges[cluster_index(frag_coord, u_viewport_size, view_depth)];
  vec3 v = normalize(u_camera_position.xyz - s.position);
  vec3 color = shade_unlit_terms(s, u_ambient.rgb);
  uint end = min(range.offset + range.count, u_list_info.x);
  for (uint i = range.offset; i < end; ++i) color += shade_light(s, v, u_lights[u_light_indices[i]]);
  return color;
}
