// One level of the bloom chain on the way up (upsample.frag and
// upsample.comp run it per texel of the level): this level's downsampled
// image plus the level below it (half this size) spread by a 3x3 tent
// filter, so each level adds a wider, softer glow to the narrower ones above.
#include "post/bloom/bloom.glsl"

layout(binding = 0) uniform sampler2D u_level;  // this level, downsampled
layout(binding = 1) uniform sampler2D u_below;  // the level below, upsampled
uniform vec2 u_level_size;
uniform vec2 u_below_size;

vec3 below_texel(ivec2 p) { return texelFetch(u_below, clamp(p, ivec2(0), ivec2(u_below_size) - 1), 0).rgb; }

// The level's texel `pixel`.
vec3 bloom_upsample(ivec2 pixel) {
  // Each level halves the one above it (an odd last row or column is
  // folded into its neighbour by the downsample's clamp): texel i of this
  // level lies over texel i / 2 of the one below, exactly as it was made.
  vec2 at = (vec2(pixel) + 0.5) * 0.5;
  vec3 tent = vec3(0.0);
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) {
      vec3 tap;
      BLOOM_BILINEAR(below_texel, at + vec2(x, y), tap);
      tent += tap * float((2 - abs(x)) * (2 - abs(y)));
    }
  }
  return texelFetch(u_level, pixel, 0).rgb + tent / 16.0;
}
