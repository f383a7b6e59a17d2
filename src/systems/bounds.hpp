// The bounds system (PostUpdate, before the camera): each frame gives every
// entity with Transform + MeshInstance its WorldBounds (the box of its mesh's
// triangles, transformed) and sets the SceneBounds resource to their union, so
// boxes follow entities that move.
#pragma once

#include "ecs/scheduler.hpp"

namespace atrium {

// Needs the AssetManager resource; adds SceneBounds when the registry lacks it.
void register_bounds(ecs::Scheduler& scheduler);

// One pass of the system, for callers that need bounds before the first frame.
void update_bounds(ecs::Registry& registry);

}  // namespace atrium
