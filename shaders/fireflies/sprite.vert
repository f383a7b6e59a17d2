#version 450 core
// The fireflies' sprites (src/systems/fireflies/firefly_sprites.cpp): one
// camera-facing quad per instance, centred on its firefly, its radius from the
// sprite's instanced attributes (so that every tier draws them, storage
// buffers or not); the fragment shader turns it into a glowing disc.
#include "common/clip.glsl"
#include "common/frame.glsl"

// C++ twin: FireflySprites::Sprite, one per instance.
layout(location = 0) in vec4 a_position_size;  // xyz world position, w radius (metres)
layout(location = 1) in vec4 a_color;          // rgb linear colour

out vec2 v_corner;
flat out vec3 v_color;

void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  vec2 corner = corners[gl_VertexID];
  // The view matrix's rows are the camera's axes in world space.
  vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]);
  vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]);
  vec3 world = a_position_size.xyz + (right * corner.x + up * corner.y) * a_position_size.w;
  gl_Position = clip_position(u_view_projection * vec4(world, 1.0));
  v_corner = corner;
  v_color = a_color.rgb;
}
