// The camera system (PostUpdate): turns the first entity with Transform + Camera
// into the frame's ViewState (view and projection matrices). Stored views set a
// camera's Transform from yaw and pitch through apply_view.
#pragma once

#include "assets/scene.hpp"
#include "components/camera.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

void register_camera(ecs::Scheduler& scheduler);

// The rotation that looks along yaw/pitch (yaw 0 = -Z, 90 = +X; pitch up > 0).
[[nodiscard]] glm::quat camera_rotation(float yaw_degrees, float pitch_degrees);

// Moves every camera entity to `view`.
void apply_view(ecs::Registry& registry, const assets::NamedView& view);

}  // namespace atrium
