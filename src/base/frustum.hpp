// A view frustum as six planes and the tests against it that frustum culling,
// shadow selection and the shadow atlas share. Plain geometry: no ECS, no GL.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace atrium {

// The six planes (xyz: inward normal, w: offset) of the frustum of a
// view-projection matrix with clip z in [0, 1], either depth direction.
// Planes from a matrix are not unit length; each normal's length is kept for
// the sphere test, which frustum culling runs once per meshlet in view.
struct Frustum {
  std::array<glm::vec4, 6> planes;
  std::array<float, 6> lengths;
};

[[nodiscard]] inline Frustum frustum_of(const glm::mat4& m) {
  // Gribb and Hartmann: a clip-space bound is a plane over the matrix's rows.
  const glm::vec4 x{m[0][0], m[1][0], m[2][0], m[3][0]};
  const glm::vec4 y{m[0][1], m[1][1], m[2][1], m[3][1]};
  const glm::vec4 z{m[0][2], m[1][2], m[2][2], m[3][2]};
  const glm::vec4 w{m[0][3], m[1][3], m[2][3], m[3][3]};
  // -w <= x, y <= w; 0 <= z <= w holds for both depth directions.
  Frustum frustum{{w + x, w - x, w + y, w - y, z, w - z}, {}};
  for (std::size_t i = 0; i < frustum.planes.size(); ++i) frustum.lengths[i] = glm::length(glm::vec3(frustum.planes[i]));
  return frustum;
}

// False only when the box lies wholly outside one plane; boxes that cross a
// corner outside two planes are kept (conservative, never drops what shows).
// Non-finite planes keep every box.
[[nodiscard]] inline bool intersects(const Frustum& frustum, glm::vec3 min, glm::vec3 max) {
  for (const glm::vec4& plane : frustum.planes) {
    // The box's corner farthest along the plane's normal.
    const glm::vec3 corner{plane.x >= 0.0f ? max.x : min.x, plane.y >= 0.0f ? max.y : min.y, plane.z >= 0.0f ? max.z : min.z};
    if (glm::dot(glm::vec3(plane), corner) + plane.w < 0.0f) return false;
  }
  return true;
}

// True only when the box lies wholly inside every plane: then so does all it
// holds, and its parts need no test of their own. Non-finite planes contain nothing.
[[nodiscard]] inline bool contains(const Frustum& frustum, glm::vec3 min, glm::vec3 max) {
  for (const glm::vec4& plane : frustum.planes) {
    // The box's corner nearest along the plane's normal.
    const glm::vec3 corner{plane.x >= 0.0f ? min.x : max.x, plane.y >= 0.0f ? min.y : max.y, plane.z >= 0.0f ? min.z : max.z};
    if (!(glm::dot(glm::vec3(plane), corner) + plane.w >= 0.0f)) return false;
  }
  return true;
}

// The same for a sphere.
[[nodiscard]] inline bool intersects(const Frustum& frustum, glm::vec3 center, float radius) {
  for (std::size_t i = 0; i < frustum.planes.size(); ++i) {
    const glm::vec4& plane = frustum.planes[i];
    if (glm::dot(glm::vec3(plane), center) + plane.w < -radius * frustum.lengths[i]) return false;
  }
  return true;
}

}  // namespace atrium
