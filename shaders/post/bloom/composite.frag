#version 450 core
// The bloomed image as a full-screen pass (composite.glsl); with MSAA it runs
// once per sample (gl_SampleID) and keeps every sample.
#include "post/bloom/composite.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
#ifdef MSAA_SAMPLES
  out_color = bloom_composite(pixel, gl_SampleID, bloom_glow(pixel));
#else
  out_color = bloom_composite(pixel, 0, bloom_glow(pixel));
#endif
}
