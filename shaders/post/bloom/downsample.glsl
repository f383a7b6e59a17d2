// One level of the bloom chain from the level above it, at half its size
// (downsample.frag and downsample.comp run it per texel of the level):
// Jimenez's 13-tap filter (SIGGRAPH 2014, "Next Generation Post Processing in
// Call of Duty: Advanced Warfare"), five overlapping 2x2 boxes of 2x2 texels.
// FIRST_LEVEL reads the lit image (each pixel's samples averaged with MSAA)
// and weights each box by 1 / (1 + luma) (Karis's average), so a lone very
// bright pixel cannot flicker into a blotch as the camera moves.
#include "common/msaa.glsl"
#include "post/bloom/bloom.glsl"

#ifdef FIRST_LEVEL
layout(binding = 0) uniform target2D u_source;
#else
layout(binding = 0) uniform sampler2D u_source;
#endif
uniform vec2 u_source_size;

vec3 source_texel(ivec2 p) {
  p = clamp(p, ivec2(0), ivec2(u_source_size) - 1);
#ifdef FIRST_LEVEL
  vec3 sum = vec3(0.0);
  for (int i = 0; i < kSamples; ++i) sum += fetch_sample(u_source, p, i).rgb;
  return sum / float(kSamples);
#else
  return texelFetch(u_source, p, 0).rgb;
#endif
}

// One of the five boxes: four corner samples `d` texels apart from corner `c`.
vec3 group(ivec2 c, int d, out float weight) {
  vec3 g = 0.25 * (BLOOM_BOX(source_texel, c) + BLOOM_BOX(source_texel, c + ivec2(d, 0)) + BLOOM_BOX(source_texel, c + ivec2(0, d)) +
                   BLOOM_BOX(source_texel, c + ivec2(d, d)));
#ifdef FIRST_LEVEL
  weight = 1.0 / (1.0 + bloom_luma(g));
#else
  weight = 1.0;
#endif
  return g;
}

// The level's texel `o`.
vec3 bloom_downsample(ivec2 o) {
  // Its centre in the source: the corner between its 2x2 texels.
  ivec2 c = 2 * o + 1;
  float w0, w1, w2, w3, w4;
  vec3 inner = group(c + ivec2(-1, -1), 2, w0);
  vec3 g1 = group(c + ivec2(-2, -2), 2, w1);
  vec3 g2 = group(c + ivec2(0, -2), 2, w2);
  vec3 g3 = group(c + ivec2(-2, 0), 2, w3);
  vec3 g4 = group(c, 2, w4);
  // The inner box weighs a half, each outer one an eighth.
  w0 *= 0.5;
  w1 *= 0.125;
  w2 *= 0.125;
  w3 *= 0.125;
  w4 *= 0.125;
  vec3 sum = inner * w0 + g1 * w1 + g2 * w2 + g3 * w3 + g4 * w4;
  return sum / (w0 + w1 + w2 + w3 + w4);
}
