#include "render/lighting/light_falloff.hpp"

#include <algorithm>
#include <cmath>

namespace atrium::lighting {

float light_attenuation(float distance, float radius) {
  if (!(radius > 0.0f)) return 0.0f;
  const float d = std::max(distance, kMinLightDistance);
  const float ratio = distance / radius;
  const float ratio4 = ratio * ratio * ratio * ratio;
  const float window = std::clamp(1.0f - ratio4, 0.0f, 1.0f);
  return window * window / (d * d);
}

float light_radius_from_intensity(const glm::vec3& color, float intensity) {
  const float brightest = std::max({color.r, color.g, color.b}) * intensity;
  return brightest > 0.0f ? std::sqrt(brightest / kRadiusThreshold) : 0.0f;
}

float intensity_for_radius(const glm::vec3& color, float radius) {
  const float brightest = std::max({color.r, color.g, color.b, 1e-6f});
  return radius * radius * kRadiusThreshold / brightest;
}

}  // namespace atrium::lighting
