#version 450 core
// Light volumes, lighting pass: shades the pixels the volume covers with its one
// light, reading the surface from the G-buffer; additively blended into the HDR
// target. With DIRECTIONAL_ONLY it is a full-screen pass for one directional
// light instead (u_light_index), which has no volume: one pass per light, as a
// loop over the whole buffer that skips the others would evaluate every light
// where the driver runs both sides of a branch (llvmpipe).
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/lighting_targets.glsl"

#ifdef DIRECTIONAL_ONLY
uniform uint u_light_index;
#else
flat in uint v_light;
#endif

// Tests before the shader, for two reasons. The stencil's reset to zero must
// reach every sample the volume covers, also those the shader discards (no
// surface; a sphere reaching past the far plane counts there): a count left
// behind on an MSAA edge's empty sample lets the per-pixel draw after the
// per-sample one light that pixel twice. And counting (COUNT_LIGHTS) has side
// effects, which would otherwise make GL run the shader before the tests.
layout(early_fragment_tests) in;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
#ifdef DIRECTIONAL_ONLY
  add_light(sum, s, v, light_at(u_light_index));
#else
  add_light_as(sum, s, v, light_at(v_light), kShadowedLights);
#endif
  // Additive: every target gains this pass's light.
  write_lighting(vec3(0.0), sum);
}
