#version 450 core
// Light volumes, lighting pass: shades the pixels the volume covers with its one
// light, reading the surface from the G-buffer; additively blended into the HDR
// target. With DIRECTIONAL_ONLY it is a full-screen pass over the directional
// lights instead, which have no volume.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/shading.glsl"

#ifndef DIRECTIONAL_ONLY
flat in uint v_light;
#endif

// Counting has side effects, which make GL run the shader before the depth and
// stencil tests; count only what passes them, as a GPU's early tests would.
#ifdef COUNT_LIGHTS
layout(early_fragment_tests) in;
#endif


layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 v = normalize(u_camera_position.xyz - s.position);
#ifdef DIRECTIONAL_ONLY
  vec3 color = vec3(0.0);
  for (uint i = 0u; i < u_light_count; ++i) {
    if (uint(u_lights[i].color_kind.w) == kLightDirectional) color += shade_light(s, v, u_lights[i]);
  }
  out_color = vec4(color, 1.0);
#else
  out_color = vec4(shade_light(s, v, u_lights[v_light]), 1.0);
#endif
}
