#version 450 core
// Depth-only passes over alpha-masked surfaces (clustered forward+'s depth
// pre-pass, shadow maps; the others go through common/mesh.vert with
// POSITION_ONLY and common/depth_only.frag): writes depth only, and discards
// fragments below the cutoff, or they would hide (or shadow) what is behind holes.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#include "common/shading_depth.glsl"

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
  write_shading_depth();
}
