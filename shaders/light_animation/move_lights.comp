#version 450 core
// Reads the frame's lights as the CPU sent them and the animation clock;
// writes where each point light that carries a motion (render::with_motion)
// is now. The light animation's GPU half: a million moving lights cost the
// CPU nothing a frame (systems/light_animation.cpp).
layout(local_size_x = 64) in;

#define MOVES_LIGHTS
#include "common/lights.glsl"

uniform uint u_light_count;
uniform float u_time;  // LightAnimationSettings::time, seconds

// C++ twin: render::moves_on_gpu.
bool moves_on_gpu(Light light) { return uint(light.color_kind.w) == kLightPoint && light.direction.w != 0.0; }

// C++ twin: animated_position (src/components/light.cpp): round a horizontal
// circle through the origin, with a gentle vertical bob.
vec3 moved_position(vec3 origin, float radius, float phase, float angular_speed, float time) {
  // Within one turn: a GPU's fast cosine loses accuracy far from zero, and
  // the angle grows with the clock.
  const float kTurn = 6.28318531;
  float angle = phase + angular_speed * time;
  angle -= kTurn * floor(angle / kTurn);
  vec3 start = vec3(cos(phase), 0.25 * sin(2.0 * phase), sin(phase));
  return origin + radius * (vec3(cos(angle), 0.25 * sin(2.0 * angle), sin(angle)) - start);
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_light_count) return;
  Light light = u_lights[i];
  if (!moves_on_gpu(light)) return;
  u_lights[i].position_radius.xyz = moved_position(light.direction.xyz, light.direction.w, light.spot.x, light.spot.y, u_time);
}
