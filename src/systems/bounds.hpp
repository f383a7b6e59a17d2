// The bounds system (PostUpdate, before the camera): gives every entity with
// Transform + MeshInstance its WorldBounds (the boxes of its mesh's primitives,
// transformed, and their union), recomputed when the entity's model matrix or
// mesh changes, and sets the SceneBounds resource to their union each frame, so
// boxes follow entities that move. SceneBounds is the one notion of the
// scene's extent at run time: the World seeds it with the box the scene
// declares (assets::SceneDescription::bounds), which it keeps while nothing
// draws a triangle.
#pragma once

#include "ecs/scheduler.hpp"

namespace atrium {

// Needs the AssetManager resource; adds SceneBounds when the registry lacks it.
void register_bounds(ecs::Scheduler& scheduler);

// One pass of the system, for callers that need bounds before the first frame.
void update_bounds(ecs::Registry& registry);

}  // namespace atrium
