// Per-frame constants shared by every pass. C++ twin: FrameUniforms in
// src/systems/lighting/frame_uniforms.hpp (its size is static_asserted).
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

// View depth (metres in front of the camera) of a depth-buffer value, for the
// perspective projection built from u_near and u_far.
float view_depth_from_depth(float depth) {
  float ndc = depth * 2.0 - 1.0;
  return 2.0 * u_near * u_far / (u_far + u_near - ndc * (u_far - u_near));
}
