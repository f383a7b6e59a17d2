#include "components/transform.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace atrium {

glm::mat4 to_matrix(const Transform& transform) {
  return glm::translate(glm::mat4(1.0f), transform.position) * glm::mat4_cast(transform.rotation) *
         glm::scale(glm::mat4(1.0f), transform.scale);
}

std::optional<Transform> from_matrix(const glm::mat4& matrix) {
  Transform t;
  t.position = glm::vec3(matrix[3]);
  glm::mat3 axes(matrix);
  for (int c = 0; c < 3; ++c) {
    t.scale[c] = glm::length(axes[c]);
    if (!(t.scale[c] > 0.0f) || !std::isfinite(t.scale[c])) return std::nullopt;
    axes[c] /= t.scale[c];
  }
  // A mirroring matrix: one negative scale keeps the rotation proper.
  if (glm::determinant(axes) < 0.0f) {
    t.scale.x = -t.scale.x;
    axes[0] = -axes[0];
  }
  t.rotation = glm::normalize(glm::quat_cast(axes));
  const bool finite = std::isfinite(t.position.x) && std::isfinite(t.position.y) && std::isfinite(t.position.z) &&
                      std::isfinite(t.rotation.w) && std::isfinite(t.rotation.x) && std::isfinite(t.rotation.y) &&
                      std::isfinite(t.rotation.z);
  if (!finite) return std::nullopt;
  return t;
}

}  // namespace atrium
