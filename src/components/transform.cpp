#include "components/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace atrium {

glm::mat4 to_matrix(const Transform& transform) {
  return glm::translate(glm::mat4(1.0f), transform.position) * glm::mat4_cast(transform.rotation) *
         glm::scale(glm::mat4(1.0f), transform.scale);
}

}  // namespace atrium
