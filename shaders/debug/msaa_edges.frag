#version 450 core
// MSAA edges view: over the lit image, the pixels whose G-buffer samples differ
// (the ones the deferred modes shade per sample; gbuffer_samples_differ, the
// test the edge-marking pass runs) in red, the rest dimmed. Without MSAA no
// pixel is an edge.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  // Blended over the image: red edges, a dark veil elsewhere.
  out_color = gbuffer_samples_differ(ivec2(gl_FragCoord.xy)) ? vec4(1.0, 0.1, 0.1, 1.0) : vec4(0.0, 0.0, 0.0, 0.6);
}
