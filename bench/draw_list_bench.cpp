// The CPU side of gathering a frame's draws, ms per frame: build_draw_list
// (render/frame/draw_list.hpp) over the twelve-courtyard grid
// (scenes/courtyard-grid.json, 3M triangles) from its views 1 and 2, in each
// selection a frame asks for: everything in view (occlusion culling off), one
// command per primitive or meshlet (occlusion culling on the GPU), and the
// shown-last-frame list (on the CPU); and the frustum culling system that
// marks what those lists gather (systems/frustum_culling.hpp). The grid's
// frames on an H200 spent 4.5 ms of renderer CPU time outside their passes
// with GPU culling.
#include <memory>

#include <benchmark/benchmark.h>

#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "components/visibility.hpp"
#include "gfx/context.hpp"
#include "render/frame/draw_list.hpp"
#include "systems/frustum_culling.hpp"

namespace atrium {
namespace {

World& grid_world(int view, CullingDevice device) {
  static const auto context = gfx::HeadlessContext::create();
  static std::unique_ptr<World> world;
  static std::pair<int, CullingDevice> loaded{0, CullingDevice::Automatic};
  if (!world || loaded != std::pair{view, device}) {
    WorldOptions options;
    options.scene = ATRIUM_SCENE_DIR "/courtyard-grid.json";
    options.size = {320, 180};
    options.view = view;
    options.lights = 1024;
    options.culling_device = device;
    world.reset();
    world = std::make_unique<World>(options);
    // Culling state settles over a few frames (shown last frame, revealed).
    for (int f = 0; f < 3; ++f) world->frame(1.0 / 60.0);
    loaded = {view, device};
  }
  return *world;
}

void run(benchmark::State& state, render::DrawSelection selection, CullingDevice device) {
  World& world = grid_world(static_cast<int>(state.range(0)), device);
  ecs::Registry& registry = world.registry();
  const auto& assets = registry.resource<assets::AssetManager>();
  const auto& gpu = registry.resource<render::GpuAssets>();
  const glm::mat4 view = registry.resource<ViewState>().view;
  std::size_t commands = 0, instance_bytes = 0;
  for (auto _ : state) {
    const render::DrawList list = render::build_draw_list(registry, assets, gpu, view, selection);
    commands = list.commands.size();
    instance_bytes = list.instances.size() * sizeof(render::InstanceData) + list.slots.size() * sizeof(render::InstanceSlot);
    benchmark::DoNotOptimize(list.commands.data());
  }
  state.counters["commands"] = static_cast<double>(commands);
  // What the frame uploads for its instances: records and their slots.
  state.counters["instance_bytes"] = static_cast<double>(instance_bytes);
  std::size_t entities = 0;
  registry.view<Transform, MeshInstance>().each([&](ecs::Entity, const Transform&, const MeshInstance&) { ++entities; });
  state.counters["entities"] = static_cast<double>(entities);
}

void BM_DrawListInView(benchmark::State& state) { run(state, render::DrawSelection::InView, CullingDevice::Gpu); }
void BM_DrawListEachInView(benchmark::State& state) { run(state, render::DrawSelection::EachInView, CullingDevice::Gpu); }
void BM_DrawListShownLastFrame(benchmark::State& state) { run(state, render::DrawSelection::ShownLastFrame, CullingDevice::Cpu); }

// The frustum and cone tests of every primitive and meshlet, from the frame's camera.
void BM_FrustumCulling(benchmark::State& state) {
  World& world = grid_world(static_cast<int>(state.range(0)), CullingDevice::Gpu);
  ecs::Registry& registry = world.registry();
  for (auto _ : state) update_frustum_culling(registry);
  const auto& stats = registry.resource<CullingStats>();
  state.counters["meshlets_tested"] = static_cast<double>(stats.meshlets);
  state.counters["meshlets_visible"] = static_cast<double>(stats.meshlets_visible);
}

BENCHMARK(BM_FrustumCulling)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DrawListInView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DrawListEachInView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DrawListShownLastFrame)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace atrium

BENCHMARK_MAIN();
