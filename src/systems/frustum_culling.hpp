// The frustum culling system (PostUpdate, after bounds and camera): tests every
// primitive box of every WorldBounds against the camera's view frustum, then the
// meshlets of large primitives against the frustum and their normal cones
// against the eye, and marks what is in view in each entity's Visibility
// (seen::kInView per primitive and meshlet), so that every pass of every
// technique draws only what the camera can see. RendererSettings::
// frustum_culling off marks everything in view (for comparisons).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "assets/mesh_asset.hpp"
#include "components/bounds.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

// The six planes (xyz: inward normal, w: offset) of the frustum of a
// view-projection matrix with clip z in [0, 1], either depth direction.
struct Frustum {
  std::array<glm::vec4, 6> planes;
};

[[nodiscard]] Frustum frustum_of(const glm::mat4& view_projection);
// False only when the box lies wholly outside one plane; boxes that cross a
// corner outside two planes are kept (conservative, never drops what shows).
// Non-finite planes keep every box.
[[nodiscard]] bool intersects(const Frustum& frustum, glm::vec3 min, glm::vec3 max);
// The same for a sphere.
[[nodiscard]] bool intersects(const Frustum& frustum, glm::vec3 center, float radius);
// Whether every triangle of the meshlet faces away from `eye` (its normal cone
// says so); false when the cone cannot tell.
[[nodiscard]] bool faces_away(const MeshletBounds& meshlet, glm::vec3 eye);

// Calls `run(first_index, index_count)` (within the primitive's indices) for
// each run of consecutive meshlets that `keep(m)` accepts (m indexes
// `meshlets`), so that a pass draws one range per run rather than one per
// meshlet.
template <typename Keep, typename Run>
void for_each_meshlet_run(std::span<const assets::Meshlet> meshlets, Keep keep, Run run) {
  std::uint32_t first = 0, count = 0;
  for (std::size_t m = 0; m < meshlets.size(); ++m) {
    if (!keep(m)) {
      if (count > 0) run(first, count);
      count = 0;
    } else if (count > 0 && first + count == meshlets[m].first_index) {
      count += meshlets[m].index_count;
    } else {
      if (count > 0) run(first, count);
      first = meshlets[m].first_index;
      count = meshlets[m].index_count;
    }
  }
  if (count > 0) run(first, count);
}

// Needs ViewState and RendererSettings; adds Visibility to entities with
// WorldBounds and sets the CullingStats resource.
void register_frustum_culling(ecs::Scheduler& scheduler);

// One pass of the system (tests; callers that cull outside the schedule).
void update_frustum_culling(ecs::Registry& registry);

}  // namespace atrium
