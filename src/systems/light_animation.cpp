#include "systems/light_animation.hpp"

#include <memory>
#include <optional>
#include <span>
#include <utility>

#include "base/parallel.hpp"
#include "render/binding_slots.hpp"
#include "render/frame/frame_modules.hpp"
#include "render/gpu_assets.hpp"
#include "render/light_buffer.hpp"

namespace atrium {
namespace {

// Below this many animated lights a second thread costs more than it saves.
constexpr std::size_t kAnimationsPerThread = 8192;

// Moves the Transforms of the animated lights that have a `Component` along
// their circles (a walk over that component's pool, a small one).
template <typename Component>
void move_lights_with(ecs::Registry& registry, double time) {
  ecs::Registry::Lookup<const LightAnimation> animations = std::as_const(registry).lookup<LightAnimation>();
  ecs::Registry::Lookup<Transform> transforms = registry.lookup<Transform>();
  for (const ecs::Entity e : registry.entities_with<Component>()) {
    const LightAnimation* animation = animations.find(e);
    Transform* transform = animation ? transforms.find(e) : nullptr;
    if (transform) transform->position = animated_position(*animation, time);
  }
}

// Every animated light's Transform, split over threads from a few thousand
// lights: at 2^20 one thread takes tens of milliseconds. Each writes the
// Transforms of its own share.
void move_every_light(ecs::Registry& registry, double time) {
  const std::span<const ecs::Entity> entities = registry.entities_with<LightAnimation>();
  const std::span<const LightAnimation> animations = registry.components_of<LightAnimation>();
  const std::size_t shares = share_count(entities.size(), kAnimationsPerThread);
  run_in_parallel(shares, [&](std::size_t share) {
    ecs::Registry::Lookup<Transform> transforms = registry.lookup<Transform>();
    const ShareRange range = share_range(entities.size(), shares, share);
    for (std::size_t i = range.begin; i < range.end; ++i) {
      if (Transform* transform = transforms.find(entities[i])) transform->position = animated_position(animations[i], time);
    }
  });
}

// Whether some animated light is one the GPU moves (moves_on_gpu): a point
// light. Stops at the first, so a million moving point lights cost one look.
bool any_moves_on_gpu(const ecs::Registry& registry, const LightAnimationSettings& settings) {
  for (const ecs::Entity e : registry.entities_with<LightAnimation>()) {
    if (moves_on_gpu(settings, registry.has<SpotCone>(e), registry.has<DirectionalLight>(e))) return true;
  }
  return false;
}

// The GPU half: after the LightBuffer has sent the records (point lights
// carry their motion, render::with_motion), one invocation a light places
// each moving one at the clock's time, before anything reads the lights.
// A frame where neither the clock nor the buffer moved since the pass last
// ran (paused, nothing sent) skips it, and so does one where only spot and
// directional lights animate (the CPU moves those): the buffer holds the
// result, and at 2^20 lights a pass over every record is not free even on a GPU.
class MotionPass {
 public:
  void add_pass(render::FrameBuild& build) {
    const auto* settings = build.registry.try_resource<LightAnimationSettings>();
    const auto* buffer = build.registry.try_resource<render::LightBuffer>();
    if (!settings || !settings->on_gpu || !buffer || build.frame.lights.empty() || !any_moves_on_gpu(build.registry, *settings)) return;
    const Placed now{buffer->buffer.id(), buffer->sends, static_cast<std::uint32_t>(build.frame.lights.size()), static_cast<float>(settings->time)};
    if (placed_ && *placed_ == now) return;
    if (!program_) program_ = &build.registry.resource<render::GpuAssets>().shaders().get({"light_animation/move_lights.comp"});
    const render::ResourceId lights = build.frame.light_buffer;
    build.graph.add_pass("light motion", [&](render::PassBuilder& pass) {
      pass.read(lights, render::Access::Storage);
      pass.write(lights, render::Access::Storage);
    }, [this, lights, now](const render::PassResources& res) {
      program_->use();
      program_->set("u_light_count", now.count);
      program_->set("u_time", now.time);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kLightStorageBinding, res.buffer(lights));
      glDispatchCompute((now.count + 63) / 64, 1, 1);
      placed_ = now;  // here, not when added: a frame that built the pass but did not run it placed nothing
    });
  }
  void invalidate() {
    program_ = nullptr;
    placed_.reset();
  }

 private:
  // What the buffer held when the pass last placed its lights.
  struct Placed {
    GLuint buffer = 0;
    std::uint64_t sends = 0;  // render::LightBuffer::sends
    std::uint32_t count = 0;
    float time = 0.0f;
    bool operator==(const Placed&) const = default;
  };
  gfx::ShaderProgram* program_ = nullptr;
  std::optional<Placed> placed_;
};

}  // namespace

void register_light_animation(ecs::Scheduler& scheduler, ecs::Registry& registry) {
  if (auto* modules = registry.try_resource<render::FrameModules>()) {
    auto motion = std::make_shared<MotionPass>();
    modules->add({render::FrameStage::BeforeLighting, "light motion", [motion](render::FrameBuild& build) { motion->add_pass(build); },
                  [motion] { motion->invalidate(); }});
  }
  scheduler.add(ecs::Phase::Update, "light_animation", [](ecs::Registry& registry) {
    auto* settings = registry.try_resource<LightAnimationSettings>();
    if (!settings || settings->paused) return;
    settings->time += registry.resource<ecs::FrameClock>().delta_seconds;
    if (!settings->on_gpu) {
      move_every_light(registry, settings->time);
      return;
    }
    // Point lights move on the GPU (moves_on_gpu): only the others here.
    move_lights_with<SpotCone>(registry, settings->time);
    move_lights_with<DirectionalLight>(registry, settings->time);
  });
}

}  // namespace atrium
