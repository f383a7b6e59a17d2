#version 450 core
// Forward shading, the reference baseline: every fragment that survives the
// depth test at the time it is drawn loops over every light (no pre-pass, so
// later-occluded fragments are shaded too). Writes linear HDR colour; the
// deferred techniques draw blended geometry with it too.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#include "common/shading.glsl"

// Counting has side effects, which make GL run the shader before the depth and
// stencil tests; count only what passes them, as a GPU's early tests would.
#ifdef COUNT_LIGHTS
layout(early_fragment_tests) in;
#endif

layout(location = 0) out vec4 out_color;

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
  out_color = vec4(shade_all_lights(s), s.alpha);
}
