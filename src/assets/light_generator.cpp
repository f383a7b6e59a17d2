#include <algorithm>
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
  // The same lights from every build: mt19937's numbers are standard, but
  // std::uniform_real_distribution's mapping is each standard library's own
  // (the browser build's libc++ is not the native libstdc++), and so is the
  // order a constructor's arguments are evaluated in. This is libstdc++'s
  // mapping (generate_canonical: one 32-bit draw over 2^32), taken in the
  // order GCC evaluated it, so that native pictures stay as they were.
  std::mt19937 random(generator.seed);
  auto unit = [&] {
    const float value = static_cast<float>(random()) / 4294967296.0f;
    return value < 1.0f ? value : std::nextafter(1.0f, 0.0f);
  };
  std::vector<SceneLight> lights;
  lights.reserve(generator.count);
  for (std::uint32_t i = 0; i < generator.count; ++i) {
    SceneLight light;
    light.generated = true;
    const float z = unit(), y = unit(), x = unit();
    light.position = generator.box_min + (generator.box_max - generator.box_min) * glm::vec3(x, y, z);
    const glm::vec3 hue = hue_to_rgb(unit());
    light.color = generator.color.value_or(hue);
    light.intensity = glm::mix(generator.intensity_min, generator.intensity_max, unit());
    const float radius_pick = unit();
    if (generator.radius_range) light.radius = glm::mix(generator.radius_range->x, generator.radius_range->y, radius_pick);
    lights.push_back(light);
  }
  return lights;
}

void resize_lights(SceneDescription& scene, std::uint32_t count) {
  if (count <= scene.lights.size()) {
    scene.lights.resize(count);
    return;
  }
  LightGenerator generator;
  if (scene.fill_generator) {
    generator = *scene.fill_generator;
  } else {
    // Around the scene's bounds, grown by a quarter of the diagonal in every axis
    // so that a single object, even a flat one, is lit from outside too. A light
    // is bright only well inside its radius (irradiance is 5/256 * (radius /
    // distance)^2), so radii of three diagonals light everything clearly.
    const float diagonal = glm::length(scene.bounds.max - scene.bounds.min);
    const glm::vec3 margin(0.25f * diagonal);
    const float radius = std::max(3.0f * diagonal, 1e-6f);
    generator.box_min = scene.bounds.min - margin;
    generator.box_max = scene.bounds.max + margin;
    generator.intensity_min = generator.intensity_max = radius * radius * 5.0f / 256.0f;
    generator.seed = 7;
  }
  // Generated lights are regenerated from the start of their sequence, which
  // gives back the same lights first: growing keeps every existing light.
  std::erase_if(scene.lights, [](const SceneLight& light) { return light.generated; });
  generator.count = count - static_cast<std::uint32_t>(scene.lights.size());
  for (const SceneLight& light : generate_lights(generator)) scene.lights.push_back(light);
}

}  // namespace atrium::assets
