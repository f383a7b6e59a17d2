#include "systems/light_animation.hpp"

#include <cmath>
#include <span>

#include "base/parallel.hpp"

namespace atrium {
namespace {

// Below this many animated lights a second thread costs more than it saves.
constexpr std::size_t kAnimationsPerThread = 8192;

}  // namespace

glm::vec3 animated_position(const LightAnimation& animation, double time) {
  // Offset so that the circle passes through the origin at time 0: the scene
  // starts as the file placed it.
  const auto angle = static_cast<float>(animation.phase + animation.angular_speed * time);
  const glm::vec3 start(std::cos(animation.phase), 0.25f * std::sin(2.0f * animation.phase), std::sin(animation.phase));
  return animation.origin +
         animation.radius * (glm::vec3(std::cos(angle), 0.25f * std::sin(2.0f * angle), std::sin(angle)) - start);
}

void register_light_animation(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Update, "light_animation", [](ecs::Registry& registry) {
    auto* settings = registry.try_resource<LightAnimationSettings>();
    if (!settings || settings->paused) return;
    settings->time += registry.resource<ecs::FrameClock>().delta_seconds;
    // Split over threads from a few thousand lights: at 2^20 one thread takes
    // tens of milliseconds. Each writes the Transforms of its own share.
    const std::span<const ecs::Entity> entities = registry.entities_with<LightAnimation>();
    const std::span<const LightAnimation> animations = registry.components_of<LightAnimation>();
    const std::size_t shares = share_count(entities.size(), kAnimationsPerThread);
    const double time = settings->time;
    run_in_parallel(shares, [&](std::size_t share) {
      ecs::Registry::Lookup<Transform> transforms = registry.lookup<Transform>();
      const ShareRange range = share_range(entities.size(), shares, share);
      for (std::size_t i = range.begin; i < range.end; ++i) {
        if (Transform* transform = transforms.find(entities[i])) transform->position = animated_position(animations[i], time);
      }
    });
  });
}

}  // namespace atrium
