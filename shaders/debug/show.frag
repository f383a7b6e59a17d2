#version 450 core
// Debug views of the G-buffer and depth: reads one target and writes it as a
// displayable colour straight to the output (no tone mapping). One of
// SHOW_POSITION, SHOW_NORMAL, SHOW_ALBEDO, SHOW_METALLIC_ROUGHNESS and
// SHOW_EMISSIVE picks the G-buffer quantity (the debug view table's rows; in
// the light pre-pass's thin layout albedo and emissive are grey); SHOW_DEPTH
// shows the depth resource bound at unit 5 (the visualiser of depth resources).
// The overlay's thumbnails draw it into a smaller viewport: output
// pixels map to G-buffer pixels through the thumbnail origin and scale. With
// MSAA they show sample 0.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/tonemap.glsl"

layout(binding = 5) uniform target2D u_depth;
uniform vec3 u_bounds_min;
uniform vec3 u_bounds_max;
uniform vec2 u_thumbnail_origin;
uniform vec2 u_thumbnail_scale;

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2((gl_FragCoord.xy - u_thumbnail_origin) * u_thumbnail_scale);
  vec3 color = vec3(0.0);
#ifdef SHOW_DEPTH
  // Linear view depth, near white, far black, on a log scale; any depth
  // resource, with no G-buffer.
  float d = fetch_sample(u_depth, pixel, 0).r;
  color = vec3(d > kDepthFar ? 1.0 - log2(view_depth_from_depth(d) / u_near) / log2(u_far / u_near) : 0.0);
#else
  Surface s;
  if (read_gbuffer(pixel, s)) {
#if defined(SHOW_POSITION)
    color = clamp((s.position - u_bounds_min) / max(u_bounds_max - u_bounds_min, vec3(1e-6)), 0.0, 1.0);
#elif defined(SHOW_NORMAL)
    color = s.normal * 0.5 + 0.5;
#elif defined(SHOW_METALLIC_ROUGHNESS)
    color = vec3(s.metallic, s.roughness, 0.0);  // the thin layout stores no metallic: red stays 0
#elif defined(THIN_GBUFFER)
    color = vec3(0.15);  // albedo and emission are not in the thin layout: grey says so
#elif defined(SHOW_ALBEDO)
    color = linear_to_srgb(s.albedo);
#elif defined(SHOW_EMISSIVE)
    color = linear_to_srgb(tonemap_aces(s.emissive));
#endif
  }
#endif
  out_color = vec4(color, 1.0);
}
