// Reading the frame's targets with or without MSAA. With MSAA_SAMPLES (the
// renderer's global define for --msaa) every target is multisampled; a pass
// reads sample `i` of a target with fetch_sample(), and a lighting pass built
// with PER_SAMPLE runs once per sample (gl_SampleID), the others once per pixel
// reading sample 0 (src/render/lighting/sample_rate.hpp says which pixels get which);
// a compute lighting pass sets the sample it reads itself (g_sample).
#ifdef MSAA_SAMPLES
#define target2D sampler2DMS
#define utarget2D usampler2DMS
#define fetch_sample(target, pixel, i) texelFetch(target, pixel, i)
const int kSamples = MSAA_SAMPLES;
#else
#define target2D sampler2D
#define utarget2D usampler2D
#define fetch_sample(target, pixel, i) texelFetch(target, pixel, 0)
const int kSamples = 1;
#endif

#if defined(MSAA_SAMPLES) && defined(PER_SAMPLE)
#define kThisSample gl_SampleID
#elif defined(MSAA_SAMPLES) && defined(COMPUTE_STAGE)
// A compute lighting pass picks the sample it shades (common/lighting_main.glsl).
int g_sample = 0;
#define kThisSample g_sample
#else
#define kThisSample 0
#endif
