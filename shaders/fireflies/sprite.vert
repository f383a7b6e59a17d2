#version 450 core
// The fireflies' sprites (src/systems/fireflies/firefly_sprites.cpp): one
// camera-facing quad per instance, centred on its firefly, its radius from the
// sprite buffer; the fragment shader turns it into a glowing disc.
#include "common/frame.glsl"

// C++ twin: FireflySprites::Sprite.
struct Sprite {
  vec4 position_size;  // xyz world position, w radius (metres)
  vec4 color;          // rgb linear colour
};
layout(std430, binding = 12) readonly buffer SpriteBlock { Sprite u_sprites[]; };

out vec2 v_corner;
flat out vec3 v_color;

void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  const Sprite sprite = u_sprites[gl_InstanceID];
  const vec2 corner = corners[gl_VertexID];
  // The view matrix's rows are the camera's axes in world space.
  const vec3 right = vec3(u_view[0][0], u_view[1][0], u_view[2][0]);
  const vec3 up = vec3(u_view[0][1], u_view[1][1], u_view[2][1]);
  const vec3 world = sprite.position_size.xyz + (right * corner.x + up * corner.y) * sprite.position_size.w;
  gl_Position = u_view_projection * vec4(world, 1.0);
  v_corner = corner;
  v_color = sprite.color.rgb;
}
