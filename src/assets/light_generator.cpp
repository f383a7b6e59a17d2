#include <cmath>
#include <random>


#include "assets/scene.hpp"

namespace atrium::assets {
namespace {
// A saturated colour from a hue in [0, 1): the brightest channel is always 1, so
// the derived radius depends on intensity alone.
glm::vec3 hue_to_rgb(float hue) {
  const glm::vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
  glm::vec3 rgb;
  for (int c = 0; c < 3; ++c) {
    const float h = std::fmod(hue + k[c], 1.0f) * 6.0f;
    rgb[c] = glm::clamp(std::abs(h - 3.0f) - 1.0f, 0.0f, 1.0f);
  }
  // Lift the minimum so that lights read as tinted rather than pure primaries.
  return glm::mix(glm::vec3(0.25f), glm::vec3(1.0f), rgb);
}
}  // namespace

std::vector<SceneLight> generate_lights(const LightGenerator& generator) {
  std::mt19937 random(generator.seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<SceneLight> lights;
  lights.reserve(generator.count);
  for (std::uint32_t i = 0; i < generator.count; ++i) {
    SceneLight light;
    light.position = generator.box_min + (generator.box_max - generator.box_min) *
                                             glm::vec3(unit(random), unit(random), unit(random));
    light.color = hue_to_rgb(unit(random));
    light.intensity = glm::mix(generator.intensity_min, generator.intensity_max, unit(random));
    light.radius = generator.radius;
    lights.push_back(light);
  }
  return lights;
}

}  // namespace atrium::assets
