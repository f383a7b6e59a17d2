// The frustum culling system (PostUpdate, after bounds and camera): tests every
// primitive box of every WorldBounds against the camera's view frustum, then the
// meshlets of large primitives against the frustum and their normal cones
// against the eye, and marks what is in view in each entity's Visibility
// (seen::kInView per primitive and meshlet), so that every pass of every
// technique draws only what the camera can see. RendererSettings::
// frustum_culling off marks everything in view (for comparisons).
#pragma once

#include <glm/glm.hpp>

#include "base/frustum.hpp"
#include "components/bounds.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

// Whether every triangle of the meshlet faces away from `eye` (its normal cone
// says so); false when the cone cannot tell.
[[nodiscard]] bool faces_away(const MeshletBounds& meshlet, glm::vec3 eye);

// Needs ViewState and RendererSettings; adds Visibility to entities with
// WorldBounds and sets the CullingStats resource.
void register_frustum_culling(ecs::Scheduler& scheduler);

// One pass of the system (tests; callers that cull outside the schedule).
void update_frustum_culling(ecs::Registry& registry);

}  // namespace atrium
