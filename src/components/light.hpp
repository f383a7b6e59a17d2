// A point light is an entity with a Transform (its position), a LightColor and,
// optionally, a LightRadius. Without a LightRadius the radius is derived from the
// colour and intensity (see systems/lighting/light_falloff.hpp).
#pragma once

#include <glm/glm.hpp>

namespace atrium {

struct LightColor {
  glm::vec3 color{1.0f};  // linear RGB, brightest channel usually 1
  float intensity = 1.0f; // radiant intensity scale: radiance at 1 m is color * intensity
};

struct LightRadius {
  float radius = 1.0f;  // metres; the light contributes nothing beyond it
};

}  // namespace atrium
