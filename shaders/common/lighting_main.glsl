// The entry point of a deferred lighting pass, in the stage it is built for:
// a full-screen fragment pass (with MSAA the stencil picks the pixels each rate
// shades, sample_rate.hpp; tested before the shader, rejected pixels neither
// run nor count as shaded), or with COMPUTE_STAGE one compute invocation per
// pixel in groups of kLightingGroupSize x kLightingGroupSize, each group's
// pixels inside one 16x16 tile (render/lighting/lighting_stage.hpp). Included
// last, after the pass's shade_pixel().
#ifdef COMPUTE_STAGE
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(u_viewport_size)))) return;
  g_shaded_pixel = pixel;
  shade_pixel(pixel);
}
#else
layout(early_fragment_tests) in;

void main() { shade_pixel(ivec2(gl_FragCoord.xy)); }
#endif
