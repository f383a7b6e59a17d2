// World-space axis-aligned boxes, kept by the bounds system (systems/bounds.hpp):
// WorldBounds on every entity with a MeshInstance, SceneBounds (a resource) over
// all of them. The camera fits its depth planes to SceneBounds.
#pragma once

#include <glm/glm.hpp>

namespace atrium {

struct WorldBounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool empty = true;  // the instance draws no triangle
};

struct SceneBounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool empty = true;  // nothing in the scene draws a triangle
};

}  // namespace atrium
