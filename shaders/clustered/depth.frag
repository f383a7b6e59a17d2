#version 450 core
// Clustered forward+, depth pre-pass: writes depth only, so that the shading
// pass shades each pixel once. Alpha-masked fragments below the cutoff are
// discarded here too, or they would hide what is behind their holes.
#include "common/frame.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv[5];
in vec4 v_color;

void main() {
  count_fragment();
  if ((v_material_flags & kMaterialAlphaMasked) != 0u) {
    Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
    if (s.alpha < material_alpha_cutoff()) discard;
  }
}
