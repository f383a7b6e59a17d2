// Extreme light counts: a million lights render in the tiled and clustered
// modes when their lists fit, are refused with the memory they would need when
// they do not, and modes whose pixels loop over every light refuse counts the
// driver cannot loop over. Glass no longer forces that refusal in the tiled and
// clustered modes, which shade it from their lists; the light-volume modes still
// shade it over every light and refuse. After a refusal the world renders again
// with fewer.
#include <gmock/gmock.h>

#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "assets/image.hpp"
#include "gfx/limits.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using LightLimits = testing::GlTest;
using ::testing::HasSubstr;

constexpr std::uint32_t kMillion = 1'000'000;

// Pixels of `lit` brighter than in `dark` by more than `levels` in some channel, and darker.
std::pair<int, int> brighter_and_darker(const assets::Image& lit, const assets::Image& dark, int levels) {
  std::pair<int, int> counts{0, 0};
  for (std::size_t p = 0; p < lit.rgba.size(); p += 4) {
    bool brighter = false, darker = false;
    for (std::size_t c = p; c < p + 3; ++c) {
      brighter = brighter || lit.rgba[c] > dark.rgba[c] + levels;
      darker = darker || lit.rgba[c] + levels < dark.rgba[c];
    }
    counts.first += brighter;
    counts.second += darker;
  }
  return counts;
}

std::string refusal(World& world) {
  try {
    world.frame(0.0);
  } catch (const gfx::ResourceLimitError& e) {
    return e.what();
  }
  return "(no refusal)";
}

TEST_F(LightLimits, AMillionSmallLightsRenderAlikeInTiledAndClusteredModes) {
  // 10 cm lights: a million of them scatter specks over the courtyard.
  World world({.scene = "atrium", .lights = kMillion, .mode = "tiled-deferred", .size = {160, 90}, .light_radius = 0.1f});
  world.frame(0.0);
  const assets::Image tiled = world.renderer().read_output();
  EXPECT_EQ(world.renderer().stats().lights, kMillion);
  for (const char* mode : {"clustered-deferred", "clustered-forward"}) {
    world.set_mode(mode);
    world.frame(0.0);
    EXPECT_GE(assets::psnr(tiled, world.renderer().read_output()), 50.0) << mode << " against tiled-deferred";
  }
  world.set_light_count(0);
  world.frame(0.0);
  const auto [brighter, darker] = brighter_and_darker(tiled, world.renderer().read_output(), 4);
  EXPECT_GT(brighter, 100) << "the million lights light the scene";
  EXPECT_EQ(darker, 0);
}

TEST_F(LightLimits, AMillionLightsWhoseListsCannotFitAreRefusedNamingTheMemory) {
  // With their own radii (metres each) the lists would need hundreds of MiB.
  World world({.scene = "atrium", .lights = kMillion, .mode = "clustered-deferred", .size = {64, 36}});
  // The whole frustum slice per cluster (pixel bounds keep these lists small enough).
  world.registry().resource<RendererSettings>().technique_options.cluster_bounds = ClusterBounds::Grid;
  const std::string message = refusal(world);
  EXPECT_THAT(message, HasSubstr("clustered-deferred with 1000000 lights at 64x36: the light lists need "));
  EXPECT_THAT(message, ::testing::MatchesRegex(".*need [0-9,]+ entries \\([0-9.]+ (MiB|GiB)\\), more than one storage buffer may "
                                             "hold here \\([0-9.]+ MiB, GL_MAX_SHADER_STORAGE_BLOCK_SIZE\\); use fewer lights.*"));
  world.set_light_count(64);
  world.frame(0.0);
  EXPECT_EQ(world.renderer().stats().lights, 64u) << "a refused frame leaves the world usable";
}

TEST_F(LightLimits, ModesThatLoopOverEveryLightRefuseWhatTheDriverCannotLoop) {
  const std::uint32_t limit = gfx::shader_loop_limit();
  if (!limit) GTEST_SKIP() << "this driver has no loop limit";
  World world({.scene = "atrium", .lights = limit + 1, .mode = "forward", .size = {32, 18}});
  for (const char* mode : {"forward", "deferred", "deferred-radius"}) {
    world.set_mode(mode);
    EXPECT_THAT(refusal(world), HasSubstr(std::string(mode) + " with " + std::to_string(limit + 1) +
                                          " lights: each pixel loops over every light, and this driver ends a shader's "
                                          "loops after " + std::to_string(limit) + " iterations"));
  }
  world.set_mode("tiled-deferred");
  world.set_light_radius(0.2f);
  world.frame(0.0);
  EXPECT_EQ(world.renderer().stats().lights, limit + 1) << "tiled lists hold only the lights that reach a tile";
}

TEST_F(LightLimits, GlassUnderMoreLightsThanTheDriverCanLoopRendersAlikeInTiledAndClusteredModes) {
  const std::uint32_t limit = gfx::shader_loop_limit();
  if (!limit) GTEST_SKIP() << "this driver has no loop limit";
  const std::string glass = std::string(ATRIUM_SOURCE_DIR) + "/tests/data/gltf-tools/blender-glass.glb";
  WorldOptions options{.scene = glass, .lights = limit + 1, .mode = "clustered-deferred", .size = {160, 90}};
  options.light_radius = 0.4f;
  World world(options);
  world.frame(0.0);
  const assets::Image clustered = world.renderer().read_output();
  EXPECT_EQ(world.renderer().stats().lights, limit + 1);
  for (const char* mode : {"clustered-forward", "tiled-deferred"}) {
    world.set_mode(mode);
    world.frame(0.0);
    EXPECT_GE(assets::psnr(clustered, world.renderer().read_output()), 50.0) << mode << " against clustered-deferred";
  }
  // They shade the panes over every light: the panes are in view.
  for (const char* mode : {"light-volumes", "light-volumes-instanced"}) {
    world.set_mode(mode);
    EXPECT_THAT(refusal(world), HasSubstr(std::string(mode) + " with " + std::to_string(limit + 1) +
                                          " lights: the scene's blended surfaces are shaded forward over every light"));
  }
  world.set_mode("tiled-deferred");
  world.set_light_count(0);
  world.frame(0.0);
  const auto [brighter, darker] = brighter_and_darker(clustered, world.renderer().read_output(), 4);
  EXPECT_GT(brighter, 100) << "the lights light the scene";
  EXPECT_EQ(darker, 0);
}

}  // namespace
}  // namespace atrium
