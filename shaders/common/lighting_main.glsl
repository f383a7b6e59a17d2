// The entry point of a deferred lighting pass, in the stage it is built for:
// a full-screen fragment pass (with MSAA the stencil picks the pixels each rate
// shades, sample_rate.hpp; tested before the shader, rejected pixels neither
// run nor count as shaded), or with COMPUTE_STAGE one compute invocation per
// pixel in groups of kLightingGroupSize x kLightingGroupSize, each group's
// pixels inside one 16x16 tile (render/lighting/lighting_stage.hpp), with MSAA
// the edges' extra samples spread over the group. Included last, after the
// pass's shade_pixel() (and common/gbuffer.glsl).
#ifdef COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;

#ifdef MSAA_SAMPLES
// With MSAA the group first shades every pixel once from sample 0, storing to
// all its samples, or to sample 0 alone where the pixel's samples differ
// (gbuffer_samples_differ: the edges the fragment stage marks in the
// stencil). Those pixels' other samples go to a list in shared memory that the
// whole group then shades, one sample an invocation (Lauritzen, "Deferred
// Rendering for Current and Future Rendering Pipelines", 2010): an edge pixel
// does not keep its neighbours' invocations idle while it shades kSamples times.
const uint kGroupPixels = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
shared uint s_edge_samples[kGroupPixels * uint(kSamples - 1)];  // group pixel | sample << 16
shared uint s_edge_sample_count;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(pixel, ivec2(u_viewport_size)));
  if (gl_LocalInvocationIndex == 0u) s_edge_sample_count = 0u;
  barrier();
  bool edge = inside && gbuffer_samples_differ(pixel);
  if (inside) {
    g_shaded_pixel = pixel;
    g_shaded_samples = edge ? 1u : (1u << kSamples) - 1u;
    shade_pixel(pixel);
  }
  if (edge) {
    uint first = atomicAdd(s_edge_sample_count, uint(kSamples - 1));
    for (int i = 1; i < kSamples; ++i) s_edge_samples[first + uint(i - 1)] = gl_LocalInvocationIndex | (uint(i) << 16);
  }
  barrier();
  ivec2 origin = ivec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy);
  for (uint k = gl_LocalInvocationIndex; k < s_edge_sample_count; k += kGroupPixels) {
    uint entry = s_edge_samples[k];
    uint local = entry & 0xffffu;
    g_sample = int(entry >> 16);
    g_shaded_samples = 1u << g_sample;
    g_shaded_pixel = origin + ivec2(local % gl_WorkGroupSize.x, local / gl_WorkGroupSize.x);
    shade_pixel(g_shaded_pixel);
  }
}
#else
void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  g_shaded_pixel = pixel;
  shade_pixel(pixel);
}
#endif
#else
layout(early_fragment_tests) in;

void main() { shade_pixel(ivec2(gl_FragCoord.xy)); }
#endif
