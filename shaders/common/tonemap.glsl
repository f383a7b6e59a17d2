// HDR to display: exposure, the ACES filmic curve (Narkowicz's fit), then the
// exact sRGB transfer function.
#include "common/frame.glsl"
#include "common/msaa.glsl"

vec3 tonemap_aces(vec3 x) {
  const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// The display colour of one pixel of an HDR target. With MSAA this is the
// resolve: each sample is exposed and tone-mapped and the results averaged, so
// a bright light's edge against a dark wall stays smooth (averaging HDR values
// first would let the bright side's value win the pixel).
vec3 display_color(target2D hdr, ivec2 pixel) {
  vec3 mapped = vec3(0.0);
  for (int i = 0; i < kSamples; ++i) mapped += tonemap_aces(fetch_sample(hdr, pixel, i).rgb * u_exposure);
  return linear_to_srgb(mapped / float(kSamples));
}
