#version 450 core
// Scene geometry for every pass that rasterises meshes (forward shading, the
// G-buffer pass, depth pre-passes): clip-space position plus world position,
// normal, tangent, each texture slot's UV, the vertex colour and the material
// for material evaluation.
// Each vertex finds its instance's record through a_instance (the
// instance-slot attribute, offset by the draw's base instance: render::InstanceSlot). With
// POSITION_ONLY (depth-only passes over surfaces without alpha tests) it
// computes the clip-space position alone; with SHADOW_PASS it projects with
// u_shadow_view_projection (a shadow map's view) instead of the camera's.
#include "common/clip.glsl"
#include "common/frame.glsl"
#include "common/material_table.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_tangent;
layout(location = 3) in vec2 a_uv0;
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_color;
// x: the record; y: where the draw's triangles start in its primitive.
layout(location = 6) in uvec2 a_instance;

#include "common/instances.glsl"

#ifdef NO_STORAGE_BUFFERS
// Without base instances (WebGL2, GLES 3.0) a_instance.x is the draw's first
// instance, set as a constant attribute, and gl_InstanceID counts from it
// (the tier's records are laid out slot by slot).
uint instance_index() { return a_instance.x + uint(gl_InstanceID); }
#else
uint instance_index() { return a_instance.x; }
#endif

#define MESH_VERTEX_STAGE
#include "common/mesh_interface.glsl"

#ifdef SHADOW_PASS
uniform mat4 u_shadow_view_projection;
#endif

// Every pass that draws the same mesh computes the same depth: the depth
// pre-pass of forward+ and its shading pass compare with LEQUAL.
invariant gl_Position;

void main() {
  Instance instance = instance_at(instance_index());
  vec4 world = instance.model * vec4(a_position, 1.0);
#ifdef SHADOW_PASS
  gl_Position = clip_position(u_shadow_view_projection * world);
#else
  gl_Position = clip_position(u_view_projection * world);
#endif
#ifdef VISIBILITY_ID
  v_first_triangle_id = instance.material.y + a_instance.y;
#endif
#ifndef POSITION_ONLY
  v_position = world.xyz;
  v_normal = mat3(instance.normal_matrix) * a_normal;
  // A mirroring model matrix (negative determinant) turns the bitangent that
  // cross(normal, tangent) gives, so the handedness turns with it.
  float handedness = determinant(mat3(instance.model)) < 0.0 ? -a_tangent.w : a_tangent.w;
  v_tangent = vec4(mat3(instance.model) * a_tangent.xyz, handedness);
  Material material = material_at(instance.material.x);
  // Each slot's KHR_texture_transform, applied once per vertex: an affine map
  // commutes with interpolation, and fragments then take derivatives of values
  // no storage read feeds (llvmpipe's helper invocations read zeros from
  // storage buffers).
  for (int slot = 0; slot < 5; ++slot) {
    vec3 uv = vec3((material.uv_sets & (1u << slot)) != 0u ? a_uv1 : a_uv0, 1.0);
    v_uv[slot] = vec2(dot(material.uv_transform[2 * slot].xyz, uv), dot(material.uv_transform[2 * slot + 1].xyz, uv));
  }
  v_material_flags = material.flags;
  v_color = a_color;
  v_material = instance.material.x;
#endif
}
