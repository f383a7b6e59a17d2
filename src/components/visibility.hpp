// What the camera sees of an entity this frame, written by the frustum culling
// system (systems/frustum_culling.hpp) and read by every pass that draws scene
// geometry, through the frame's draw list.
#pragma once

#include <cstdint>
#include <vector>

namespace atrium {

// A run of one primitive's visible meshlets: its indices
// [first_index, first_index + index_count).
struct VisibleRange {
  std::uint32_t primitive = 0;
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
};

struct Visibility {
  bool any = true;  // some primitive of the entity is visible
  // One flag per primitive of the entity's mesh (1: inside or crossing the
  // view frustum), in the mesh's order; empty means all visible.
  std::vector<std::uint8_t> primitives;
  // For visible primitives cut into meshlets: the runs of meshlets that are in
  // the frustum and do not face away, by primitive. A visible primitive with no
  // range here draws whole.
  std::vector<VisibleRange> ranges;
};

// The culling system's count of the last frame, for stats and tests.
struct CullingStats {
  std::size_t objects = 0;             // entities with a mesh
  std::size_t objects_visible = 0;
  std::size_t primitives = 0;          // primitive instances
  std::size_t primitives_visible = 0;
  std::size_t meshlets = 0;            // of the primitive instances in the frustum
  std::size_t meshlets_visible = 0;    // in the frustum and not facing away
};

}  // namespace atrium
