#version 450 core
// Clustered forward+ shading: after the depth pre-pass, each visible fragment
// evaluates its material and only its cluster's lights.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#include "common/cluster_shading.glsl"

#ifdef COUNT_LIGHTS
layout(early_fragment_tests) in;
#endif

layout(location = 0) out vec4 out_color;

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
  out_color = vec4(shade_unlit_terms(s, u_ambient.rgb) + light_total(shade_cluster_lights(s, gl_FragCoord.xy)), s.alpha);
}
