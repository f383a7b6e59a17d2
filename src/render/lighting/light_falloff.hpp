// The one C++ definition of point-light falloff, twin of
// shaders/common/attenuation.glsl (tests/render/lighting/light_falloff_test.cpp renders
// the GLSL and compares). Inverse-square falloff times a smooth window that
// reaches exactly zero at the light's radius, so every technique that stops at
// the radius draws the same picture as one that never stops.
#pragma once

#include <glm/glm.hpp>

namespace atrium::lighting {

// Below this, radiance from a light is treated as invisible: 5/256 of the
// light's brightest channel (the reference's threshold).
inline constexpr float kRadiusThreshold = 5.0f / 256.0f;
// Distances under 1 cm are clamped so a light touching a surface stays finite.
inline constexpr float kMinLightDistance = 0.01f;

// Fraction of the light's intensity arriving at `distance` (0 at and beyond radius).
[[nodiscard]] float light_attenuation(float distance, float radius);

// The distance at which color * intensity / d^2 falls to kRadiusThreshold in
// the brightest channel. 0 for a black light.
[[nodiscard]] float light_radius_from_intensity(const glm::vec3& color, float intensity);
// Its inverse: the intensity whose derived radius is `radius` (a black light is
// treated as a faint white one, so the result stays finite).
[[nodiscard]] float intensity_for_radius(const glm::vec3& color, float radius);

}  // namespace atrium::lighting
