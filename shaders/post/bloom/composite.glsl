// The bloomed image (composite.frag and composite.comp): each sample of the
// colour image moved towards the glow by the bloom's strength,
// mix(colour, glow, strength). The glow is the top of the upsampled chain,
// the sum of every level, divided by the number of levels so that it holds
// the image's energy: bloom spreads light, it adds none.
#include "common/msaa.glsl"
#include "post/bloom/bloom.glsl"

layout(binding = 0) uniform target2D u_color;
layout(binding = 1) uniform sampler2D u_glow;
uniform vec2 u_glow_size;
uniform vec2 u_size;
uniform float u_strength;
uniform float u_levels;

vec3 glow_texel(ivec2 p) { return texelFetch(u_glow, clamp(p, ivec2(0), ivec2(u_glow_size) - 1), 0).rgb; }

// The glow at the centre of `pixel`.
vec3 bloom_glow(ivec2 pixel) {
  vec3 glow;
  BLOOM_BILINEAR(glow_texel, (vec2(pixel) + 0.5) * 0.5, glow);  // the glow is half this size (upsample.glsl)
  return glow / u_levels;
}

// Sample `i` of `pixel`, bloomed.
vec4 bloom_composite(ivec2 pixel, int i, vec3 glow) {
  vec4 color = fetch_sample(u_color, pixel, i);
  return vec4(mix(color.rgb, glow, u_strength), color.a);
}
