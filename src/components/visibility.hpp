// What the camera sees of an entity this frame, written by the frustum culling
// system (systems/frustum_culling.hpp) and read by every pass that draws scene
// geometry, through the frame's draw list.
#pragma once

#include <cstdint>
#include <vector>

namespace atrium {

struct Visibility {
  bool any = true;  // some primitive of the entity is visible
  // One flag per primitive of the entity's mesh (1: inside or crossing the
  // view frustum), in the mesh's order; empty means all visible.
  std::vector<std::uint8_t> primitives;
};

// The culling system's count of the last frame, for stats and tests.
struct CullingStats {
  std::size_t objects = 0;             // entities with a mesh
  std::size_t objects_visible = 0;
  std::size_t primitives = 0;          // primitive instances
  std::size_t primitives_visible = 0;
};

}  // namespace atrium
