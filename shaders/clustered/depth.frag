#version 450 core
// Clustered forward+, depth pre-pass of alpha-masked surfaces (the others go
// through common/mesh.vert with POSITION_ONLY and common/depth_only.frag):
// writes depth only, so that the shading pass shades each pixel once, and
// discards fragments below the cutoff, or they would hide what is behind holes.
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
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
}
