#version 450 core
// The visibility buffer's geometry pass: writes the identifier of each visible
// triangle (its record's first identifier plus gl_PrimitiveID, which counts
// from 0 in every draw and instance) and nothing else. Alpha-masked materials
// (ALPHA_TEST) test their alpha here, and only here: the resolve trusts that
// what the buffer holds was kept. With MSAA it also writes the shading depth
// (common/shading_depth.glsl), from which light assignment marks clusters.
#include "common/frame.glsl"
#include "common/fragment_count.glsl"
#define SHADING_DEPTH_LOCATION 1
#include "common/shading_depth.glsl"
// Before material.glsl, which includes it too: a file is included once, and
// there it would sit inside the ALPHA_TEST branch.
#include "common/mesh_interface.glsl"
#ifdef ALPHA_TEST
#include "common/material.glsl"
#endif
layout(location = 0) out uint out_id;

void main() {
  count_fragment();
#ifdef ALPHA_TEST
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
#endif
  out_id = v_first_triangle_id + uint(gl_PrimitiveID);
  write_shading_depth();
}
