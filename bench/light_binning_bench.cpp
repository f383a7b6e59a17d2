// CPU light binning (render/lighting/cpu_light_lists.hpp), the compute-free
// tier's light assignment: ms per frame for the clustered modes' 16x9x32 grid
// at 1920x1080, lights in a courtyard-sized box at constant density (4 m of
// reach at 1,024 lights, shrinking as they grow), on one thread and on every
// core. ClusterGrid holds GL buffers, so a headless context is made first.
#include <cmath>
#include <random>

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gfx/context.hpp"
#include "gfx/depth.hpp"
#include "render/lighting/cpu_light_lists.hpp"

namespace {
using namespace atrium;

std::vector<render::GpuLight> courtyard_lights(std::size_t count) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> x(-17.0f, 17.0f), y(0.0f, 14.9f), z(-14.0f, 14.0f);
  const float radius = 4.0f * std::cbrt(1024.0f / static_cast<float>(count));
  std::vector<render::GpuLight> lights(count);
  for (render::GpuLight& light : lights) {
    light.position_radius = glm::vec4(x(random), y(random), z(random), radius);
    light.color_kind = glm::vec4(1.0f, 1.0f, 1.0f, static_cast<float>(render::GpuLightKind::Point));
  }
  return lights;
}

void BM_BinLightsInClusters(benchmark::State& state) {
  static const auto context = gfx::HeadlessContext::create();
  const auto lights = courtyard_lights(static_cast<std::size_t>(state.range(0)));
  lighting::ClusterGrid grid({16, 9, 32});
  grid.update(gfx::perspective(glm::radians(60.0f), 1920.0f / 1080.0f, 0.05f, 60.0f), 0.05f, 60.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 2.0f, 13.0f), glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  std::size_t entries = 0;
  for (auto _ : state) {
    const lighting::CpuLightLists lists = lighting::bin_lights_in_clusters(lights, view, grid, static_cast<unsigned>(state.range(1)));
    entries = lists.indices.size();
    benchmark::DoNotOptimize(lists.indices.data());
  }
  state.counters["entries"] = static_cast<double>(entries);
  state.SetLabel(std::to_string(state.range(1)) + (state.range(1) == 1 ? " thread" : " threads"));
}
BENCHMARK(BM_BinLightsInClusters)
    ->ArgsProduct({{1024, 16384, 131072}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
