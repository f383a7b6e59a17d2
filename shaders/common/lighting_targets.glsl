// The targets a deferred lighting pass writes: the HDR colour and, with
// SPLIT_LIGHTING, the diffuse and specular light sums apart, which the
// diffuse-light and specular-light debug views show. As a fragment pass it
// draws into FrameTargets::lighting_framebuffer; as a compute pass
// (COMPUTE_STAGE, --lighting-stage compute) it stores to the same targets bound
// as images (units from kLitImageUnit, render/lighting/lighting_stage.hpp).
// The pass's file defines shade_pixel() and then includes common/lighting_main.glsl.
// With ADD_LIGHTS (a later run of a pass split by lights) add_lighting() adds
// a sum to what an earlier run wrote: read, added and stored in compute,
// blended (one plus one, LightingPass sets it) as fragments; leave_pixel()
// keeps a pixel as it is.
#include "shading.glsl"

#ifdef COMPUTE_STAGE
#ifdef ADD_LIGHTS
#define LIT_ACCESS
#else
#define LIT_ACCESS writeonly
#endif
// With MSAA the targets are multisampled and a store writes the samples that
// g_shaded_samples names (all of them unless the pass says otherwise: the
// visibility buffer's resolve shades each triangle of an edge pixel once, for
// the samples that show it). EACH_SHADED_SAMPLE runs a statement per such
// sample, LIT_AT is the sample's address in a lit image. The images are
// declared in full in each branch: the GLSL dialect rewrite
// (gfx/glsl_dialect.cpp) reads declarations before the preprocessor does, so
// a macro cannot stand for their type.
#ifdef MSAA_SAMPLES
uint g_shaded_samples = (1u << MSAA_SAMPLES) - 1u;
#define EACH_SHADED_SAMPLE(statement) for (int lit_sample = 0; lit_sample < MSAA_SAMPLES; ++lit_sample) { if ((g_shaded_samples & (1u << lit_sample)) != 0u) { statement; } }
#define LIT_AT g_shaded_pixel, lit_sample
layout(rgba16f, binding = 2) uniform LIT_ACCESS image2DMS u_lit_color;
#ifdef SPLIT_LIGHTING
layout(rgba16f, binding = 3) uniform LIT_ACCESS image2DMS u_lit_diffuse;
layout(rgba16f, binding = 4) uniform LIT_ACCESS image2DMS u_lit_specular;
#endif
#else
#define EACH_SHADED_SAMPLE(statement) { statement; }
#define LIT_AT g_shaded_pixel
layout(rgba16f, binding = 2) uniform LIT_ACCESS image2D u_lit_color;
#ifdef SPLIT_LIGHTING
layout(rgba16f, binding = 3) uniform LIT_ACCESS image2D u_lit_diffuse;
layout(rgba16f, binding = 4) uniform LIT_ACCESS image2D u_lit_specular;
#endif
#endif

void write_lighting(vec3 unlit, LightSum sum) {
  EACH_SHADED_SAMPLE(imageStore(u_lit_color, LIT_AT, vec4(unlit + light_total(sum), 1.0)))
#ifdef SPLIT_LIGHTING
  EACH_SHADED_SAMPLE(imageStore(u_lit_diffuse, LIT_AT, vec4(sum.diffuse, 1.0)); imageStore(u_lit_specular, LIT_AT, vec4(sum.specular, 1.0)))
#endif
}
#ifdef ADD_LIGHTS
void add_lighting(LightSum sum) {
  EACH_SHADED_SAMPLE(imageStore(u_lit_color, LIT_AT, imageLoad(u_lit_color, LIT_AT) + vec4(light_total(sum), 0.0)))
#ifdef SPLIT_LIGHTING
  EACH_SHADED_SAMPLE(imageStore(u_lit_diffuse, LIT_AT, imageLoad(u_lit_diffuse, LIT_AT) + vec4(sum.diffuse, 0.0));
                     imageStore(u_lit_specular, LIT_AT, imageLoad(u_lit_specular, LIT_AT) + vec4(sum.specular, 0.0)))
#endif
}
void leave_pixel() {}
#endif
#else
layout(location = 0) out vec4 out_color;
#ifdef SPLIT_LIGHTING
layout(location = 1) out vec4 out_diffuse;
layout(location = 2) out vec4 out_specular;
#endif

void write_lighting(vec3 unlit, LightSum sum) {
  out_color = vec4(unlit + light_total(sum), 1.0);
#ifdef SPLIT_LIGHTING
  out_diffuse = vec4(sum.diffuse, 1.0);
  out_specular = vec4(sum.specular, 1.0);
#endif
}
#ifdef ADD_LIGHTS
void add_lighting(LightSum sum) {
  out_color = vec4(light_total(sum), 0.0);
#ifdef SPLIT_LIGHTING
  out_diffuse = vec4(sum.diffuse, 0.0);
  out_specular = vec4(sum.specular, 0.0);
#endif
}
void leave_pixel() { discard; }
#endif
#endif

// A pixel no surface covers: the background, and no light.
void write_background() { write_lighting(u_background.rgb, no_light()); }
