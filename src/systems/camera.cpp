#include "systems/camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "gfx/depth.hpp"

namespace atrium {

glm::quat camera_rotation(float yaw_degrees, float pitch_degrees) {
  return glm::angleAxis(glm::radians(-yaw_degrees), glm::vec3(0, 1, 0)) *
         glm::angleAxis(glm::radians(pitch_degrees), glm::vec3(1, 0, 0));
}

void apply_view(ecs::Registry& registry, const assets::NamedView& view) {
  registry.view<Transform, Camera>().each([&](ecs::Entity entity, Transform& transform, Camera&) {
    transform.position = view.position;
    transform.rotation = camera_rotation(view.yaw_degrees, view.pitch_degrees);
    if (auto* angles = registry.try_get<CameraAngles>(entity)) *angles = {view.yaw_degrees, view.pitch_degrees};
    registry.add<CameraCut>(entity);
  });
}

DepthPlanes fit_depth_planes(const glm::mat4& view, glm::vec3 bounds_min, glm::vec3 bounds_max) {
  float nearest = std::numeric_limits<float>::max(), farthest = std::numeric_limits<float>::lowest();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? bounds_max.x : bounds_min.x, (corner & 2) ? bounds_max.y : bounds_min.y,
                      (corner & 4) ? bounds_max.z : bounds_min.z);
    const float depth = -(view * glm::vec4(p, 1.0f)).z;
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  // A box behind the camera, or one with no size, still gets planes in its units.
  const float size = std::max(glm::length(bounds_max - bounds_min), 1e-6f);
  const float far_plane = std::max(farthest, 1e-3f * size) * 1.01f + 1e-6f * size;
  const float near_plane = std::max(nearest * 0.99f, far_plane * kMinNearFarRatio);
  if (!std::isfinite(far_plane) || !std::isfinite(near_plane)) return {0.05f, 200.0f};
  return {near_plane, far_plane};
}

DepthPlanes settle_depth_planes(DepthPlanes previous, DepthPlanes fitted) {
  // A near plane at its floor (kMinNearFarRatio of far) is as close as planes
  // come: it holds whatever geometry is near.
  const float floor = previous.far_plane * kMinNearFarRatio * 1.0001f;
  const bool holds = previous.near_plane <= std::max(fitted.near_plane, floor) && previous.far_plane >= fitted.far_plane;
  const bool tight = previous.near_plane * 2.0f >= fitted.near_plane && previous.far_plane <= fitted.far_plane * 2.0f;
  return holds && tight ? previous : fresh_depth_planes(fitted);
}

DepthPlanes fresh_depth_planes(DepthPlanes fitted) {
  const float far_plane = fitted.far_plane * 1.25f;
  return {std::max(fitted.near_plane * 0.8f, std::min(fitted.near_plane, far_plane * kMinNearFarRatio)), far_plane};
}

void register_camera(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::PostUpdate, "camera", [](ecs::Registry& registry) {
    const glm::ivec2 size = registry.resource<Viewport>().size;
    const auto* scene = registry.try_resource<SceneBounds>();
    const glm::vec3 lo = scene ? scene->min : glm::vec3(0.0f), hi = scene ? scene->max : glm::vec3(0.0f);
    auto& state = registry.resource<ViewState>();
    std::vector<ecs::Entity> cut;
    registry.view<CameraCut>().each([&](ecs::Entity entity, const CameraCut&) { cut.push_back(entity); });
    for (const ecs::Entity entity : cut) registry.remove<CameraCut>(entity);
    state.cut = !cut.empty();
    registry.view<Transform, Camera>().each([&](const Transform& transform, const Camera& camera) {
      const float aspect = static_cast<float>(std::max(size.x, 1)) / static_cast<float>(std::max(size.y, 1));
      const glm::mat4 world = glm::translate(glm::mat4(1.0f), transform.position) * glm::mat4_cast(transform.rotation);
      state.view = glm::inverse(world);
      // A cut owes nothing to the last view: its planes are the ones a camera
      // starting here gets, so a view's clusters do not depend on the one before.
      const DepthPlanes fitted = fit_depth_planes(state.view, lo, hi);
      const DepthPlanes planes =
          state.cut ? fresh_depth_planes(fitted) : settle_depth_planes({state.near_plane, state.far_plane}, fitted);
      state.near_plane = camera.near_plane.value_or(planes.near_plane);
      state.far_plane = camera.far_plane.value_or(planes.far_plane);
      state.projection = gfx::perspective(glm::radians(camera.vertical_fov_degrees), aspect, state.near_plane, state.far_plane);
      state.view_projection = state.projection * state.view;
      state.camera_position = transform.position;
    });
  });
}

}  // namespace atrium
