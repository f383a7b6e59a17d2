// Iterating 1M entities with two components through a registry view, against a
// plain struct-of-vectors loop over the same data: what the ECS costs per entity.
#include <vector>

#include <benchmark/benchmark.h>

#include "ecs/registry.hpp"

namespace {

struct Position {
  float x, y, z;
};
struct Velocity {
  float x, y, z;
};

constexpr std::size_t kEntities = 1'000'000;
constexpr float kDelta = 1.0f / 60.0f;

void BM_PlainStructOfVectors(benchmark::State& state) {
  std::vector<Position> positions(kEntities, Position{0, 0, 0});
  std::vector<Velocity> velocities(kEntities, Velocity{1, 2, 3});
  for (auto _ : state) {
    for (std::size_t i = 0; i < kEntities; ++i) {
      positions[i].x += velocities[i].x * kDelta;
      positions[i].y += velocities[i].y * kDelta;
      positions[i].z += velocities[i].z * kDelta;
    }
    benchmark::DoNotOptimize(positions.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kEntities));
}
BENCHMARK(BM_PlainStructOfVectors)->Unit(benchmark::kMillisecond);

void BM_RegistryView(benchmark::State& state) {
  atrium::ecs::Registry registry;
  for (std::size_t i = 0; i < kEntities; ++i) {
    const auto e = registry.create();
    registry.add<Position>(e, 0.0f, 0.0f, 0.0f);
    registry.add<Velocity>(e, 1.0f, 2.0f, 3.0f);
  }
  for (auto _ : state) {
    registry.view<Position, Velocity>().each([](Position& p, const Velocity& v) {
      p.x += v.x * kDelta;
      p.y += v.y * kDelta;
      p.z += v.z * kDelta;
    });
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kEntities));
}
BENCHMARK(BM_RegistryView)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
