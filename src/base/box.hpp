// The one axis-aligned box: starts empty and grows to hold what is added.
// Importers bound models with it, the bounds system bounds instances and the
// scene (components/bounds.hpp), culling and shadows test against it.
#pragma once

#include <glm/glm.hpp>

namespace atrium {

struct Box {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool empty = true;  // holds nothing (no point, no triangle) yet

  void add(glm::vec3 point) {
    min = empty ? point : glm::min(min, point);
    max = empty ? point : glm::max(max, point);
    empty = false;
  }
  void add(const Box& other) {
    if (other.empty) return;
    add(other.min);
    add(other.max);
  }
  // The eight corners of the box [lo, hi] placed by `transform`.
  void add_box(const glm::mat4& transform, glm::vec3 lo, glm::vec3 hi) {
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
      add(glm::vec3(transform * glm::vec4(local, 1.0f)));
    }
  }
  [[nodiscard]] bool operator==(const Box&) const = default;
};

}  // namespace atrium
