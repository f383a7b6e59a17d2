// World-space axis-aligned boxes, kept by the bounds system (systems/bounds.hpp):
// WorldBounds on every entity with a MeshInstance, SceneBounds (a resource) over
// all of them. The camera fits its depth planes to SceneBounds; frustum culling
// tests the per-primitive boxes.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "assets/handles.hpp"
#include "base/box.hpp"

namespace atrium {

// A meshlet (assets/meshlets.hpp) in world space.
struct MeshletBounds {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  glm::vec3 cone_apex{0.0f};
  glm::vec3 cone_axis{0.0f, 0.0f, 1.0f};
  float cone_cutoff = 2.0f;  // > 1: never culled as facing away
};

// The instance's box (empty: it draws no triangle) and its parts'.
struct WorldBounds : Box {
  // One box per primitive of the instance's mesh, in the mesh's order.
  std::vector<Box> primitives;
  // Every primitive's meshlets in order; primitive p's are
  // [meshlet_offsets[p], meshlet_offsets[p + 1]). Normal cones only where the
  // model matrix keeps angles and winding (a rotation, a uniform scale and a
  // translation); elsewhere they never cull.
  std::vector<MeshletBounds> meshlets;
  std::vector<std::uint32_t> meshlet_offsets;
  // What the boxes were computed from: the bounds system recomputes them only
  // when the entity's model matrix or mesh changes.
  glm::mat4 model{0.0f};
  assets::MeshAssetHandle asset;
  std::uint32_t mesh = 0;
};

// Every instance's box together; while nothing draws a triangle, the box the
// scene declared (empty when it declared none). The camera fits its depth
// planes to it, the position view scales its colours to it, systems place
// what they spawn in it.
struct SceneBounds : Box {};

}  // namespace atrium
