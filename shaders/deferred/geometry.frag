#version 450 core
// Deferred geometry pass: evaluates each visible fragment's material and writes
// it to the G-buffer (alpha-masked fragments below the cutoff are discarded).
// Opaque and masked geometry only; blended geometry is drawn forward later.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#define GBUFFER_WRITE
#include "common/gbuffer.glsl"

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
  write_gbuffer(s);
}
