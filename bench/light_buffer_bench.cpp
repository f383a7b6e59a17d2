// The CPU side of many lights, ms per frame: the light animation system alone
// (systems/light_animation.hpp, every light moved), and the LightBuffer system
// (render/light_buffer.hpp), which mirrors the registry's lights into the light
// buffer, with the lights holding still (nothing to send) and all moved by the
// animation on the CPU (all sent) or on the GPU (LightAnimationSettings::on_gpu:
// the CPU's part of the window's frame on the full tier, where the records
// hold still and the GPU places them). Lights as the world spawns generated ones (Transform,
// LightColor, LightRadius, LightAnimation). At 2^20 lights the light buffer is
// the CPU share of a frame that the GPU kit's tables name as the rest of its time.
#include <cstdint>

#include <benchmark/benchmark.h>

#include "base/golden_angle.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"
#include "gfx/context.hpp"
#include "render/light_buffer.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

void spawn_generated_lights(ecs::Registry& registry, std::int64_t count) {
  for (std::int64_t i = 0; i < count; ++i) {
    const ecs::Entity e = registry.create();
    const glm::vec3 position(static_cast<float>(i % 97) * 0.3f, 1.0f + static_cast<float>(i % 13) * 0.2f, static_cast<float>(i % 89) * 0.3f);
    registry.add<Transform>(e, Transform{position});
    registry.add<LightColor>(e, glm::vec3(1.0f, 0.8f, 0.6f), 4.0f);
    registry.add<LightRadius>(e, 1.5f);
    registry.add<LightAnimation>(e, position, golden_angle_phase(static_cast<std::uint64_t>(i)));
  }
}

void run_light_buffer(benchmark::State& state, bool animated, bool on_gpu = false) {
  static const auto context = gfx::HeadlessContext::create();
  ecs::Registry registry;
  auto& settings = registry.set_resource<LightAnimationSettings>();
  settings.paused = !animated;
  settings.on_gpu = on_gpu;
  spawn_generated_lights(registry, state.range(0));
  ecs::Scheduler scheduler;
  register_light_animation(scheduler, registry);
  render::register_light_buffer(scheduler);
  scheduler.run_frame(registry, 1.0 / 60.0);  // the first frame sends every light
  for (auto _ : state) scheduler.run_frame(registry, 1.0 / 60.0);
  state.counters["sent"] = static_cast<double>(registry.resource<render::LightBuffer>().uploaded);
}

// The light animation alone, every light moved each frame (the window's and
// the page's lights; the bench's hold still).
void BM_LightAnimation(benchmark::State& state) {
  ecs::Registry registry;
  registry.set_resource<LightAnimationSettings>();
  spawn_generated_lights(registry, state.range(0));
  ecs::Scheduler scheduler;
  register_light_animation(scheduler, registry);
  for (auto _ : state) scheduler.run_frame(registry, 1.0 / 60.0);
}

void BM_LightBufferStill(benchmark::State& state) { run_light_buffer(state, false); }
void BM_LightBufferAnimated(benchmark::State& state) { run_light_buffer(state, true); }
void BM_LightBufferMovedOnGpu(benchmark::State& state) { run_light_buffer(state, true, true); }

BENCHMARK(BM_LightAnimation)->RangeMultiplier(8)->Range(1024, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LightBufferStill)->RangeMultiplier(8)->Range(1024, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LightBufferAnimated)->RangeMultiplier(8)->Range(1024, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_LightBufferMovedOnGpu)->RangeMultiplier(8)->Range(1024, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace atrium

BENCHMARK_MAIN();
