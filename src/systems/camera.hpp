// The camera system (PostUpdate): turns the first entity with Transform + Camera
// into the frame's ViewState (view and projection matrices, reversed Z as
// gfx/depth.hpp says), with near and far planes that follow the scene's bounds
// and the camera's place in them, and ViewState::cut where a CameraCut asks.
// Stored views set a camera's Transform from yaw and pitch through apply_view.
#pragma once

#include "assets/scene.hpp"
#include "components/camera.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"

namespace atrium {

void register_camera(ecs::Scheduler& scheduler);

// The far plane never comes closer than this fraction of the far plane's
// distance: with reversed float depth, 1e-4 keeps surfaces 1e-6 of their
// distance apart anywhere in the range.
inline constexpr float kMinNearFarRatio = 1e-4f;

struct DepthPlanes {
  float near_plane;
  float far_plane;
};

// Near and far planes that hold the box [bounds_min, bounds_max] seen through
// `view`: far just beyond the box's farthest corner along the view axis, near
// just before its nearest one when the camera is outside the box, else
// kMinNearFarRatio of far (a camera inside a model can come close to a wall).
[[nodiscard]] DepthPlanes fit_depth_planes(const glm::mat4& view, glm::vec3 bounds_min, glm::vec3 bounds_max);

// The planes to use this frame: last frame's while they still hold `fitted`
// and are no more than twice as loose, else `fitted` with some slack. A camera
// that moves a little keeps its projection (and the cluster grid its boxes).
[[nodiscard]] DepthPlanes settle_depth_planes(DepthPlanes previous, DepthPlanes fitted);

// `fitted` with that slack: the planes of a camera with no last frame to keep
// (its first frame, or a CameraCut).
[[nodiscard]] DepthPlanes fresh_depth_planes(DepthPlanes fitted);

// The rotation that looks along yaw/pitch (yaw 0 = -Z, 90 = +X; pitch up > 0).
[[nodiscard]] glm::quat camera_rotation(float yaw_degrees, float pitch_degrees);

// Moves every camera entity to `view`, as a cut (CameraCut).
void apply_view(ecs::Registry& registry, const assets::NamedView& view);

}  // namespace atrium
