#version 450 core
// Diffuse-light, specular-light and light-buffer views: one of the light sums a
// deferred mode wrote apart (SPLIT_LIGHTING), or the light pre-pass's summed
// diffuse light before materials, exposed and tone-mapped as the final image is,
// into the output or an overlay thumbnail (output pixels map to target pixels
// through the thumbnail origin and scale). With MSAA resolved as the final
// image is (display_color).
#include "common/frame.glsl"
#include "common/tonemap.glsl"

// SINGLE_SAMPLE: a single-sample image in a multisampled frame (a
// post-process chain's levels), which the thumbnail scale
// also stretches from its own size.
#ifdef SINGLE_SAMPLE
layout(binding = 0) uniform sampler2D u_light_sum;
#else
layout(binding = 0) uniform target2D u_light_sum;
#endif
uniform vec2 u_thumbnail_origin;
uniform vec2 u_thumbnail_scale;

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2((gl_FragCoord.xy - u_thumbnail_origin) * u_thumbnail_scale);
#ifdef SINGLE_SAMPLE
  out_color = vec4(linear_to_srgb(tonemap_aces(texelFetch(u_light_sum, pixel, 0).rgb * u_exposure)), 1.0);
#else
  out_color = vec4(display_color(u_light_sum, pixel), 1.0);
#endif
}
