#version 450 core
// Scene geometry for every pass that rasterises meshes (forward shading, the
// G-buffer pass, depth pre-passes): clip-space position plus world position,
// normal, tangent and both UV sets for material evaluation.
#include "common/frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;

out vec3 v_position;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv0;
out vec2 v_uv1;

// Every pass that draws the same mesh computes the same depth: the depth
// pre-pass of forward+ and its shading pass compare with LEQUAL.
invariant gl_Position;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_position = world.xyz;
  v_normal = u_normal_matrix * a_normal;
  v_tangent = vec4(mat3(u_model) * a_tangent.xyz, a_tangent.w);
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  gl_Position = u_view_projection * world;
}
