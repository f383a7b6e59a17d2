#version 450 core
// Forward shading, the reference baseline: every fragment that survives the
// depth test at the time it is drawn loops over every light (no pre-pass, so
// later-occluded fragments are shaded too). Writes linear HDR colour.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/shading.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv0;
in vec2 v_uv1;

layout(location = 0) out vec4 out_color;

void main() {
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv0, v_uv1, gl_FrontFacing);
  if (s.alpha < u_alpha_cutoff) discard;
  vec3 v = normalize(u_camera_position.xyz - s.position);
  vec3 color = shade_unlit_terms(s, u_ambient.rgb);
  for (uint i = 0u; i < u_light_count; ++i) color += shade_light(s, v, u_lights[i]);
  out_color = vec4(color, s.alpha);
}
