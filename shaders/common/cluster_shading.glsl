// Shading with a cluster's lights only: shared by clustered forward+ and
// clustered deferred.
#include "list_shading.glsl"
#include "clusters.glsl"

// The sum of the lights in the cluster of `s` (the unlit terms are the caller's).
LightSum shade_cluster_lights(Surface s, vec2 frag_coord) {
  float view_depth = -(u_view * vec4(s.position, 1.0)).z;
  return shade_listed_lights(s, light_range(cluster_index(frag_coord, u_viewport_size, view_depth)));
}
