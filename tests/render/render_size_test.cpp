// Extreme image sizes, headless: one pixel renders in every mode as forward
// does, an 8192x8192 image renders the picture a small one does, and a size
// beyond what the context can render is refused naming the limit.
#include <gmock/gmock.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "gfx/limits.hpp"
#include "support/box_downsample.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"

namespace atrium {
namespace {

using RenderSize = testing::GlTest;

// Under AddressSanitizer, where every byte of the big frame's read-back and
// down-sampling is checked, 8192x8192 took 157 s of a CI run: the sanitizer
// build renders 4096x4096, through the same code.
#ifdef __SANITIZE_ADDRESS__
constexpr int kBigSize = 4096;
#else
constexpr int kBigSize = 8192;
#endif

TEST_F(RenderSize, OnePixelRendersInEveryModeAsForwardDoes) {
  World world({.scene = "atrium", .lights = 24u, .mode = "forward", .size = {1, 1}});
  testing::compare_every_mode_with_forward(world, [](const std::string& mode, int view, const assets::Image& reference,
                                                      const assets::Image& image) {
    EXPECT_LE(assets::max_channel_difference(reference, image), 2) << mode << " view " << view;
  });
}

TEST_F(RenderSize, ABigSquareImageShowsWhatASmallOneShowsInForwardAndDeferred) {
  const std::string scene = std::string(ATRIUM_BIG_TEXTURE_DIR) + "/small-texture.gltf";
  World small({.scene = scene, .lights = 0u, .size = {kBigSize / 4, kBigSize / 4}});
  small.frame(0.0);
  World big({.scene = scene, .lights = 0u, .size = {kBigSize, kBigSize}});
  big.frame(0.0);
  const assets::Image image = big.renderer().read_output();
  ASSERT_EQ(image.width, kBigSize);
  ASSERT_EQ(image.height, kBigSize);
  // Only the edges differ: a pixel of the smaller image is either in or out.
  EXPECT_GE(assets::psnr(small.renderer().read_output(), testing::box_downsample(image, 4, false)), 35.0);
  big.set_mode("clustered-deferred");  // the biggest G-buffer and the most bins
  big.frame(0.0);
  EXPECT_GE(assets::psnr(image, big.renderer().read_output()), kMinimumPsnr) << "clustered-deferred against forward";
}

TEST_F(RenderSize, ASizeBeyondWhatTheContextRendersIsRefusedNamingTheLimit) {
  World world({.scene = "atrium", .lights = 4u, .mode = "deferred", .size = {32, 18}});
  const glm::ivec2 limit = gfx::max_render_size();
  world.set_size({limit.x + 1, 8});
  try {
    world.frame(0.0);
    FAIL() << "no refusal";
  } catch (const gfx::ResourceLimitError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(std::to_string(limit.x + 1) + "x8 is larger than this context can render (" +
                                               std::to_string(limit.x) + "x" + std::to_string(limit.y)));
  }
  world.set_size({32, 18});
  world.frame(0.0);
  EXPECT_EQ(world.renderer().read_output().width, 32);
}

}  // namespace
}  // namespace atrium
