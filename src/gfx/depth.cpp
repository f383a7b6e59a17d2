#include "gfx/depth.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace atrium::gfx {

void use_depth_convention() { glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE); }

glm::mat4 perspective(float vertical_fov_radians, float aspect, float near, float far) {
  // GLM's zero-to-one projection with its planes swapped maps near to 1 and far to 0.
  return glm::perspectiveRH_ZO(vertical_fov_radians, aspect, far, near);
}

float view_depth_from_depth(float depth, float near, float far) { return near * far / (near + depth * (far - near)); }

}  // namespace atrium::gfx
