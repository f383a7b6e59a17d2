#version 450 core
// MSAA edge marking, after the G-buffer pass: reads every sample of each pixel
// and keeps (does not discard) the pixels whose samples differ. The pass's
// stencil op sets the edge bit there (sample_rate.hpp); lighting passes then
// shade those pixels per sample and every other pixel once.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"

void main() {
  if (!gbuffer_samples_differ(ivec2(gl_FragCoord.xy))) discard;
}
