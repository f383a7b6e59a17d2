// A firefly: a small point light (with its Transform, LightColor and
// LightRadius) that wanders round `home` by up to `range` metres; fireflies
// differ by `phase`. Made and moved by the fireflies system.
#pragma once

#include <glm/glm.hpp>

namespace atrium {

struct Firefly {
  glm::vec3 home{0.0f};
  float range = 0.5f;
  float phase = 0.0f;
  float size = 0.05f;  // the sprite's radius, metres
};

}  // namespace atrium
