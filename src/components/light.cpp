#include "components/light.hpp"

#include <cmath>

namespace atrium {

glm::vec3 animated_position(const LightAnimation& animation, double time) {
  // Offset so that the circle passes through the origin at time 0: the scene
  // starts as the file placed it.
  const auto angle = static_cast<float>(animation.phase + animation.angular_speed * time);
  const glm::vec3 start(std::cos(animation.phase), 0.25f * std::sin(2.0f * animation.phase), std::sin(animation.phase));
  return animation.origin +
         animation.radius * (glm::vec3(std::cos(angle), 0.25f * std::sin(2.0f * angle), std::sin(angle)) - start);
}

}  // namespace atrium
