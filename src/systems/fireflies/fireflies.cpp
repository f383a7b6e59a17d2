#include "systems/fireflies/fireflies.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "base/golden_angle.hpp"
#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/system_options.hpp"
#include "components/transform.hpp"
#include "systems/fireflies/firefly.hpp"
#include "systems/fireflies/firefly_sprites.hpp"

namespace atrium {
namespace {

constexpr const char* kOption = "fireflies";
constexpr int kMaxFireflies = 4096;

// A low-discrepancy point in [0, 1)^3 (the R3 sequence), so that any count
// of fireflies spreads evenly and firefly k stays where it was as N grows.
glm::vec3 spread(int k) {
  const glm::vec3 step(0.8191725134f, 0.6710436067f, 0.5497004779f);
  return glm::fract(glm::vec3(0.5f) + step * static_cast<float>(k + 1));
}

// Where a firefly is at `time` seconds: round its home on a slow, uneven loop.
glm::vec3 wander(const Firefly& f, double time) {
  const float t = static_cast<float>(time);
  return f.home + f.range * glm::vec3(std::sin(0.7f * t + f.phase), 0.4f * std::sin(1.1f * t + 2.0f * f.phase),
                                      std::cos(0.5f * t + 3.0f * f.phase));
}

void update_fireflies(ecs::Registry& registry) {
  const int wanted = std::clamp(static_cast<int>(registry.resource<SystemOptions>().value(kOption)), 0, kMaxFireflies);
  std::vector<ecs::Entity> existing;
  registry.view<Firefly>().each([&](ecs::Entity e, const Firefly&) { existing.push_back(e); });
  for (std::size_t i = static_cast<std::size_t>(wanted); i < existing.size(); ++i) registry.destroy(existing[i]);
  const SceneBounds& scene = registry.resource<SceneBounds>();
  const glm::vec3 extent = glm::max(scene.max - scene.min, glm::vec3(1.0f));
  // Sized to the scene: a reach of a few percent of its diagonal.
  const float reach = std::clamp(0.04f * glm::length(extent), 0.4f, 4.0f);
  for (int k = static_cast<int>(existing.size()); k < wanted; ++k) {
    Firefly firefly;
    // The lower two thirds of the scene, where its floors and walls are.
    const glm::vec3 at = spread(k) * glm::vec3(1.0f, 0.66f, 1.0f);
    firefly.home = scene.min + at * extent;
    firefly.range = 0.5f * reach;
    firefly.phase = golden_angle_phase(static_cast<std::uint64_t>(k));
    firefly.size = 0.06f * reach;
    const ecs::Entity e = registry.create();
    registry.add<Firefly>(e, firefly);
    registry.add<Transform>(e, Transform{firefly.home});
    registry.add<LightColor>(e, glm::vec3(1.0f, 0.85f, 0.35f), 0.5f * reach * reach);
    registry.add<LightRadius>(e, reach);
  }
  const double time = registry.resource<LightAnimationSettings>().time;
  registry.view<Firefly, Transform>().each([&](ecs::Entity, const Firefly& f, Transform& transform) { transform.position = wander(f, time); });
}

}  // namespace

void register_fireflies(ecs::Scheduler& scheduler, ecs::Registry& registry) {
  registry.resource<SystemOptions>().declare(kOption, "fireflies", 0.0, kMaxFireflies);
  auto sprites = std::make_shared<FireflySprites>();
  registry.resource<render::FrameModules>().add({render::FrameStage::AfterLighting, kOption,
                                                  [sprites](render::FrameBuild& build) { sprites->add_pass(build); },
                                                  [sprites] { sprites->invalidate(); }});
  scheduler.add(ecs::Phase::Update, kOption, update_fireflies);
}

}  // namespace atrium
