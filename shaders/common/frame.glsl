// Per-frame constants shared by every pass. C++ twin: FrameUniforms in
// src/render/frame/frame_uniforms.hpp (its size is static_asserted).
layout(std140, binding = 0) uniform FrameBlock {
  mat4 u_view;
  mat4 u_projection;
  mat4 u_view_projection;
  mat4 u_inverse_view_projection;
  vec4 u_camera_position;   // xyz world position
  vec4 u_ambient;           // rgb: ambient = u_ambient * albedo * occlusion
  vec4 u_background;        // rgb: linear HDR colour behind all geometry
  vec2 u_viewport_size;
  float u_exposure;
  uint u_light_count;
  float u_near;
  float u_far;
  vec2 u_frame_padding;
};

// The depth convention (C++ twin: src/gfx/depth.hpp): reversed Z, the near
// plane at depth 1, the far plane and the cleared background at 0.
const float kDepthFar = 0.0;
const float kDepthNear = 1.0;

// View depth (metres in front of the camera) of a depth-buffer value, for the
// perspective projection built from u_near and u_far.
float view_depth_from_depth(float depth) {
  return u_near * u_far / (u_near + depth * (u_far - u_near));
}
