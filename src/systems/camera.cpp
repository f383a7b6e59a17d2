#include "systems/camera.hpp"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "components/frame_resources.hpp"

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
  });
}

void register_camera(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::PostUpdate, "camera", [](ecs::Registry& registry) {
    const glm::ivec2 size = registry.resource<Viewport>().size;
    auto& state = registry.resource<ViewState>();
    registry.view<Transform, Camera>().each([&](const Transform& transform, const Camera& camera) {
      const float aspect = static_cast<float>(std::max(size.x, 1)) / static_cast<float>(std::max(size.y, 1));
      const glm::mat4 world = glm::translate(glm::mat4(1.0f), transform.position) * glm::mat4_cast(transform.rotation);
      state.view = glm::inverse(world);
      state.projection = glm::perspective(glm::radians(camera.vertical_fov_degrees), aspect, camera.near_plane, camera.far_plane);
      state.view_projection = state.projection * state.view;
      state.camera_position = transform.position;
      state.near_plane = camera.near_plane;
      state.far_plane = camera.far_plane;
    });
  });
}

}  // namespace atrium
