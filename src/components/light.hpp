// A point light is an entity with a Transform (its position), a LightColor and,
// optionally, a LightRadius. Without a LightRadius the radius is derived from the
// colour and intensity (see render/lighting/light_falloff.hpp). A SpotCone or a
// DirectionalLight component changes the kind.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace atrium {

// The most lights a world holds (command line, scene files, the window): 2^20,
// the "million lights" that light-culling papers measure.
inline constexpr std::uint32_t kMaxLights = 1u << 20;

struct LightColor {
  glm::vec3 color{1.0f};  // linear RGB, brightest channel usually 1
  float intensity = 1.0f; // radiant intensity scale: radiance at 1 m is color * intensity
};

struct LightRadius {
  float radius = 1.0f;  // metres; the light contributes nothing beyond it
};

// Makes a light a spot light: it shines along its Transform's -Z axis, at full
// intensity within inner_cone radians of the axis and not at all beyond outer_cone.
struct SpotCone {
  float inner_cone = 0.0f;
  float outer_cone = 0.7853982f;
};

// Makes a light directional: parallel rays along its Transform's -Z axis, no
// position, no falloff, no radius.
struct DirectionalLight {};

// Moves a light from `origin` (systems/light_animation.hpp) round a horizontal
// circle of `radius` metres through it, with a gentle vertical bob; lights
// differ by `phase`. While it moves, where it is comes from here, not from its
// Transform: on the GPU (LightAnimationSettings::on_gpu) its Transform stays
// at the origin.
struct LightAnimation {
  glm::vec3 origin{0.0f};
  float phase = 0.0f;
  float radius = 0.5f;
  float angular_speed = 0.6f;  // radians per second
};

// Where `animation` puts its light `time` seconds in. The GPU's twin is
// moved_position in shaders/light_animation/move_lights.comp.
[[nodiscard]] glm::vec3 animated_position(const LightAnimation& animation, double time);
// The farthest animated_position ever puts its light from the origin: the
// circle's diameter (the bob is level again wherever the circle is widest,
// half a turn on), so that a test against a sphere grown by this much holds
// at every time without computing where the light is.
[[nodiscard]] inline float animated_reach(const LightAnimation& animation) { return 2.0f * std::abs(animation.radius); }

// Shared by every LightAnimation: `p` in the window pauses them.
struct LightAnimationSettings {
  bool paused = false;
  double time = 0.0;  // seconds of animation so far (stops while paused)
  // Point lights move on the GPU: the LightBuffer sends their LightAnimation
  // once, in the light's record, and the light_animation system's compute
  // pass places them every frame, so that a million moving lights cost the
  // CPU nothing. Set by the World where the context runs compute shaders;
  // spot and directional lights (whose records have no room for a motion)
  // and every light on the compute-free tier move on the CPU.
  bool on_gpu = false;
};

// Whether a light with a LightAnimation moves on the GPU: a point light (no
// SpotCone, no DirectionalLight) while the settings say so.
[[nodiscard]] inline bool moves_on_gpu(const LightAnimationSettings& settings, bool spot, bool directional) {
  return settings.on_gpu && !spot && !directional;
}

}  // namespace atrium
