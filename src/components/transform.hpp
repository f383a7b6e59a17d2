// Where an entity is: position, orientation and scale in world space.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace atrium {

struct Transform {
  glm::vec3 position{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

// The model matrix of a Transform (translate * rotate * scale).
[[nodiscard]] glm::mat4 to_matrix(const Transform& transform);

// The Transform of an affine matrix (any shear is lost); nullopt when an axis
// has zero or non-finite length.
[[nodiscard]] std::optional<Transform> from_matrix(const glm::mat4& matrix);

}  // namespace atrium
