#version 450 core
// Scene geometry for every pass that rasterises meshes (forward shading, the
// G-buffer pass, depth pre-passes): clip-space position plus world position,
// normal, tangent, both UV sets and the vertex colour for material evaluation.
// Each vertex finds its instance's transforms through a_instance (the
// instance-index attribute, offset by the draw's base instance).
#include "common/frame.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;
layout(location = 6) in uint a_instance;

// C++ twin: InstanceData in src/systems/lighting/draw_list.hpp.
struct Instance {
  mat4 model;
  mat4 normal_matrix;  // the inverse transpose in the upper-left 3x3
};
layout(std430, binding = 1) readonly buffer Instances { Instance u_instances[]; };

out vec3 v_position;
out vec3 v_normal;
out vec4 v_tangent;
out vec2 v_uv0;
out vec2 v_uv1;
out vec4 v_color;

// Every pass that draws the same mesh computes the same depth: the depth
// pre-pass of forward+ and its shading pass compare with LEQUAL.
invariant gl_Position;

void main() {
  Instance instance = u_instances[a_instance];
  vec4 world = instance.model * vec4(a_position, 1.0);
  v_position = world.xyz;
  v_normal = mat3(instance.normal_matrix) * a_normal;
  v_tangent = vec4(mat3(instance.model) * a_tangent.xyz, a_tangent.w);
  v_uv0 = a_uv0;
  v_uv1 = a_uv1;
  v_color = a_color;
  gl_Position = u_view_projection * world;
}
