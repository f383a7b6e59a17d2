#version 450 core
// Debug views of the tiled and clustered modes' binning, from the depth buffer
// and the technique's light lists: LIGHT_BINS 1 colours each pixel by the light
// count of its tile, 2 by that of its cluster (black for none, magenta where a
// light that did not fit this frame's lists reaches: those pixels shaded it
// outside their lists);
// DEPTH_SLICES colours each pixel by its cluster depth slice.
#include "common/frame.glsl"
#include "common/colour_map.glsl"
#include "common/clusters.glsl"
#include "common/msaa.glsl"
#include "common/lights.glsl"

layout(binding = 5) uniform target2D u_depth;  // with MSAA: sample 0
uniform uvec2 u_tiles;
uniform uint u_tile_size;
uniform float u_scale_max;

layout(location = 0) out vec4 out_color;

#ifdef LIGHT_BINS
// Whether a light of this frame's overflow list reaches the surface at `depth`.
bool reached_by_overflow(float depth) {
  if (overflow_count() == 0u || depth <= kDepthFar) return false;
  vec4 point = u_inverse_view_projection * vec4(gl_FragCoord.xy / u_viewport_size * 2.0 - 1.0, depth, 1.0);
  for (uint o = 0u; o < overflow_count(); ++o) {
    if (light_reaches(light_at(overflow_light(o)), point.xyz / point.w)) return true;
  }
  return false;
}
#endif

void main() {
  float depth = fetch_sample(u_depth, ivec2(gl_FragCoord.xy), 0).r;
  float view_depth = view_depth_from_depth(depth);
#ifdef DEPTH_SLICES
  // Alternate bright and dim slices so that neighbours stay apart.
  uint slice = cluster_slice(view_depth);
  vec3 color = colour_map(float(slice) / float(max(u_grid.z - 1u, 1u))) * ((slice & 1u) == 0u ? 1.0 : 0.6);
#else
#if LIGHT_BINS == 1
  uvec2 tile = uvec2(gl_FragCoord.xy) / u_tile_size;
  LightRange range = light_range(tile.y * u_tiles.x + tile.x);
#else
  LightRange range = light_range(cluster_index(gl_FragCoord.xy, u_viewport_size, view_depth));
#endif
  vec3 color = reached_by_overflow(depth) ? kHeatmapOverflow : count_colour(range.count, u_scale_max);
#endif
  // The background reads no list; it is drawn dimmed grey to set it apart.
  out_color = vec4(depth > kDepthFar ? color : vec3(0.15), 1.0);
}
