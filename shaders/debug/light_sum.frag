#version 450 core
// Diffuse-light, specular-light and light-buffer views: one of the light sums a
// deferred mode wrote apart (SPLIT_LIGHTING), or the light pre-pass's summed
// diffuse light before materials, exposed and tone-mapped as the final image is,
// into the output or an overlay thumbnail (output pixels map to target pixels
// through the thumbnail origin and scale). With MSAA each sample is tone-mapped
// and the results averaged, as the final image is.
#include "common/frame.glsl"
#include "common/tonemap.glsl"
#include "common/msaa.glsl"

layout(binding = 0) uniform target2D u_light_sum;
uniform vec2 u_thumbnail_origin;
uniform vec2 u_thumbnail_scale;

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2((gl_FragCoord.xy - u_thumbnail_origin) * u_thumbnail_scale);
  vec3 mapped = vec3(0.0);
  for (int i = 0; i < kSamples; ++i) mapped += tonemap_aces(fetch_sample(u_light_sum, pixel, i).rgb * u_exposure);
  out_color = vec4(linear_to_srgb(mapped / float(kSamples)), 1.0);
}
