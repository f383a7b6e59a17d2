// Light lists (LightIndexList) from lights of every size: a few lights each
// under thousands of tiles or clusters are shared by a work group each
// (common/light_scatter.glsl), many small ones walk their own bins, and
// either way the tiled and clustered pictures equal forward's.
#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "render/lighting/light_index_list.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using LightIndexListTest = testing::GlTest;

// 320x180 has 240 tiles: a light of 12 m covers more than a work group's 64.
constexpr glm::ivec2 kWide{320, 180};

void expect_lists_match_forward(WorldOptions options) {
  options.mode = "forward";
  World reference_world(options);
  reference_world.frame(0.0);
  const assets::Image reference = reference_world.renderer().read_output();
  for (const std::string mode : {"tiled-deferred", "clustered-forward", "clustered-deferred"}) {
    options.mode = mode;
    World world(options);
    world.frame(0.0);
    world.frame(0.0);
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode << ", " << *options.lights << " lights";
    EXPECT_EQ(world.renderer().stats().light_list_overflows, 0u) << mode;
  }
}

TEST_F(LightIndexListTest, AFewLargeLightsMatchForward) {
  expect_lists_match_forward({.scene = "atrium", .lights = 24u, .size = kWide, .light_radius = 12.0f});
}

TEST_F(LightIndexListTest, ManySmallLightsMatchForward) {
  expect_lists_match_forward({.scene = "atrium", .lights = 3000u, .size = kWide, .light_radius = 0.6f});
}

// Few lights on a GPU spread their bins over work groups sooner, so that they
// fill it; a software renderer, whose barriers cost more, keeps one rule.
TEST(LightIndexListRule, LargeLightsAreFewerCandidatesWhenTheLightsAreFewOnAGpu) {
  using lighting::LightIndexList;
  EXPECT_EQ(LightIndexList::big_light_candidates(24, false), 32u);
  EXPECT_EQ(LightIndexList::big_light_candidates(1024, false), 32u);
  EXPECT_EQ(LightIndexList::big_light_candidates(4096, false), 128u);
  EXPECT_EQ(LightIndexList::big_light_candidates(16384, false), 512u);
  EXPECT_EQ(LightIndexList::big_light_candidates(1u << 20, false), 512u);
  for (const std::uint32_t lights : {24u, 1024u, 1u << 20}) EXPECT_EQ(LightIndexList::big_light_candidates(lights, true), 512u);
}

}  // namespace
}  // namespace atrium
