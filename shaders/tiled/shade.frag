#version 450 core
// Tiled-deferred's pass over blended surfaces: forward shading of each fragment
// with its tile's lights from the blended list (assign.comp with BLENDED), whose
// depth bounds span the glass in front of the opaque surfaces.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#include "common/tile_shading.glsl"

#ifdef COUNT_LIGHTS
layout(early_fragment_tests) in;
#endif

layout(location = 0) out vec4 out_color;

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  out_color = vec4(shade_unlit_terms(s, u_ambient.rgb) + light_total(shade_tile_lights(s, gl_FragCoord.xy)), s.alpha);
}
