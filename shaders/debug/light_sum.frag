#version 450 core
// Diffuse-light, specular-light and light-buffer views: one of the light sums a
// deferred mode wrote apart (SPLIT_LIGHTING), or the light pre-pass's summed
// diffuse light before materials, exposed and tone-mapped as the final image is,
// into the output or an overlay thumbnail (output pixels map to target pixels
// through the thumbnail origin and scale). With MSAA resolved as the final
// image is (display_color).
#include "common/frame.glsl"
#include "common/tonemap.glsl"

layout(binding = 0) uniform target2D u_light_sum;
uniform vec2 u_thumbnail_origin;
uniform vec2 u_thumbnail_scale;

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2((gl_FragCoord.xy - u_thumbnail_origin) * u_thumbnail_scale);
  out_color = vec4(display_color(u_light_sum, pixel), 1.0);
}
