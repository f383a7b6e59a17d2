// CPU light binning, the compute-free tier's light assignment: the same lists
// as the GPU's clustered assignment (grid bounds, light order included) and as
// the brute-force CPU reference (every light against every cluster), on one
// thread and on several, for lights a scene draws and for the awkward ones
// (a sun, a light behind the camera, one across the near plane, one that
// covers the grid); and tile lists that hold every light the GPU's tiles
// (which have depth bounds) hold.
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "gfx/depth.hpp"
#include "render/lighting/cpu_light_lists.hpp"
#include "render/techniques/clustered/clustered.hpp"
#include "render/techniques/tiled/tiled.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using CpuLightLists = testing::GlTest;

// The lists as light indices per bin, as ClusterGrid::read_lists gives them.
std::vector<std::vector<std::uint32_t>> per_bin(const lighting::CpuLightLists& lists) {
  std::vector<std::vector<std::uint32_t>> out(lists.ranges.size());
  for (std::size_t b = 0; b < lists.ranges.size(); ++b) {
    const glm::uvec2 range = lists.ranges[b];
    out[b].assign(lists.indices.begin() + range.x, lists.indices.begin() + range.x + range.y);
  }
  return out;
}

// Draws until the GPU's lists hold every light: the first frame's total comes
// back after it (LightIndexList), so the second frame's lists are sized by it.
void draw_settled(World& world) {
  world.frame(0.0);
  world.renderer().settle();
  world.frame(0.0);
}

TEST_F(CpuLightLists, EqualTheGpuListsOfTheSameGridInLightOrder) {
  for (const ZSlicing slicing : {ZSlicing::Log, ZSlicing::Uniform}) {
    World world({.scene = "atrium", .lights = 6000u, .mode = "clustered-forward", .view = 2, .size = {160, 90}, .light_radius = 1.5f});
    auto& options = world.registry().resource<RendererSettings>().technique_options;
    options.cluster_grid = ClusterGridSize::fixed({8, 5, 12});
    options.cluster_bounds = ClusterBounds::Grid;
    options.z_slicing = slicing;
    draw_settled(world);
    const auto& technique = dynamic_cast<const techniques::ClusteredTechnique&>(*world.renderer().technique());
    const auto gpu = technique.grid().read_lists();
    const auto& lights = world.registry().resource<render::LightBuffer>().staging;
    const glm::mat4& view = world.registry().resource<ViewState>().view;
    std::size_t entries = 0;
    for (const unsigned threads : {1u, 2u, 3u}) {
      const auto cpu = per_bin(lighting::bin_lights_in_clusters(lights, view, technique.grid(), threads));
      ASSERT_EQ(cpu.size(), gpu.size());
      for (std::size_t c = 0; c < cpu.size(); ++c) EXPECT_EQ(cpu[c], gpu[c]) << "cluster " << c << ", " << threads << " threads";
      entries = 0;
      for (const auto& list : cpu) entries += list.size();
    }
    EXPECT_GT(entries, 6000u) << "lights reach several clusters";
  }
}

TEST_F(CpuLightLists, AwkwardLightsEqualTheBruteForceReference) {
  constexpr float kNear = 0.1f, kFar = 80.0f;
  lighting::ClusterGrid grid({16, 9, 24});
  grid.update(gfx::perspective(glm::radians(60.0f), 16.0f / 9.0f, kNear, kFar), kNear, kFar);
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 2.0f, 10.0f), glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  auto light = [](glm::vec3 position, float radius, render::GpuLightKind kind = render::GpuLightKind::Point) {
    render::GpuLight l{};
    l.position_radius = glm::vec4(position, radius);
    l.color_kind = glm::vec4(1.0f, 1.0f, 1.0f, static_cast<float>(kind));
    return l;
  };
  std::vector<render::GpuLight> lights{
      light(glm::vec3(0.0f), 0.0f, render::GpuLightKind::Directional),  // everywhere
      light(glm::vec3(0.0f, 2.0f, 20.0f), 3.0f),                 // behind the camera
      light(glm::vec3(0.3f, 2.0f, 10.0f), 1.0f),                 // around the eye, across the near plane
      light(glm::vec3(0.0f, 2.0f, 0.0f), 200.0f),                // covers the whole grid
      light(glm::vec3(0.0f, 2.0f, -69.0f), 12.0f),               // across the far plane
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<float> x(-30.0f, 30.0f), y(-5.0f, 15.0f), z(-90.0f, 15.0f), r(0.05f, 6.0f);
  for (int i = 0; i < 5000; ++i) lights.push_back(light(glm::vec3(x(random), y(random), z(random)), r(random)));
  const auto reference = grid.assign_on_cpu(lights, view);
  for (const unsigned threads : {1u, 2u}) {
    const auto binned = per_bin(lighting::bin_lights_in_clusters(lights, view, grid, threads));
    ASSERT_EQ(binned.size(), reference.size());
    for (std::size_t c = 0; c < binned.size(); ++c) EXPECT_EQ(binned[c], reference[c]) << "cluster " << c << ", " << threads << " threads";
  }
  EXPECT_EQ(reference[0].front(), 0u) << "the sun is in every cluster";
}

TEST_F(CpuLightLists, TileListsHoldEveryLightTheGpusTilesHold) {
  World world({.scene = "atrium", .lights = 3000u, .mode = "tiled-deferred", .view = 5, .size = {200, 120}, .light_radius = 1.0f});
  draw_settled(world);
  const auto& technique = dynamic_cast<const techniques::TiledTechnique&>(*world.renderer().technique());
  const auto gpu = technique.list().read();
  const auto& lights = world.registry().resource<render::LightBuffer>().staging;
  const ViewState& view = world.registry().resource<ViewState>();
  std::size_t gpu_entries = 0, cpu_entries = 0;
  for (const unsigned threads : {1u, 2u}) {
    const auto cpu = per_bin(lighting::bin_lights_in_tiles(lights, view.view, view.projection, {200, 120}, techniques::kTileSize,
                                                           view.near_plane, view.far_plane, threads));
    ASSERT_EQ(cpu.size(), gpu.size());
    ASSERT_EQ(cpu.size(), std::size_t{technique.tiles().x} * technique.tiles().y);
    gpu_entries = cpu_entries = 0;
    for (std::size_t t = 0; t < cpu.size(); ++t) {
      EXPECT_TRUE(std::is_sorted(cpu[t].begin(), cpu[t].end())) << "tile " << t;
      EXPECT_TRUE(std::includes(cpu[t].begin(), cpu[t].end(), gpu[t].begin(), gpu[t].end())) << "tile " << t << ", " << threads << " threads";
      gpu_entries += gpu[t].size();
      cpu_entries += cpu[t].size();
    }
  }
  EXPECT_GT(gpu_entries, 3000u);
  // Without depth bounds a tile also lists the lights in front of and behind
  // its surfaces, but not every light.
  EXPECT_GT(cpu_entries, gpu_entries);
  EXPECT_LT(cpu_entries, std::size_t{3000} * gpu.size() / 4);
}

}  // namespace
}  // namespace atrium
