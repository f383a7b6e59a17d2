// Texture upload limits: a texture wider or taller than the context allows (or
// than --max-texture-size), or one it cannot hold, is downscaled with one
// warning naming it, and draws the picture that a small texture of the same
// content draws. The data comes from tests/data/make_big_texture.py at build
// time.
#include <gmock/gmock.h>

#include "app/world.hpp"
#include "render/gpu_assets.hpp"
#include "assets/image.hpp"
#include "gfx/limits.hpp"
#include "support/gl_test.hpp"
#include "support/uploaded_texture.hpp"

namespace atrium {
namespace {

using TextureLimits = testing::GlTest;
using testing::uploaded_size;

const std::string kBig = std::string(ATRIUM_BIG_TEXTURE_DIR) + "/big-texture.gltf";
const std::string kSmall = std::string(ATRIUM_BIG_TEXTURE_DIR) + "/small-texture.gltf";

WorldOptions options(const std::string& scene, int max_texture_size = 0) {
  return {.scene = scene, .lights = 0u, .size = {160, 90}, .max_texture_size = max_texture_size};
}

assets::Image render(World& world) {
  world.frame(0.0);
  return world.renderer().read_output();
}

TEST_F(TextureLimits, ATextureOverTheCapIsDownscaledWithOneWarningAndDrawsTheSamePicture) {
  World small(options(kSmall));
  const assets::Image reference = render(small);
  EXPECT_TRUE(small.load_report().warnings.empty());

  World capped(options(kBig, 1024));
  EXPECT_THAT(capped.load_report().warnings,
              ::testing::ElementsAre(::testing::HasSubstr("texture 0 '/images/0 (quadrants-16384.png)' is 16384x16384, more than "
                                                          "--max-texture-size allows (1024); it is downscaled to 1024x1024")));
  EXPECT_EQ(uploaded_size(capped), glm::ivec2(1024, 1024));
  EXPECT_GE(assets::psnr(reference, render(capped)), 35.0) << "the 64x64 texture of the same quadrants";
}

// Up to GL_MAX_TEXTURE_SIZE as it is; where the driver still cannot hold it
// (zink over lavapipe refuses 16384x16384 with its mips for memory), halved
// until it can, with one warning that says so, and never a texture without
// storage (black, and GL errors).
TEST_F(TextureLimits, A16384TextureLoadsAtWhatTheContextAllows) {
  World small(options(kSmall));
  const assets::Image reference = render(small);
  World big(options(kBig));
  const int allowed = std::min(gfx::max_texture_size(), 16384);
  const glm::ivec2 size = uploaded_size(big);
  EXPECT_EQ(size.x, size.y);
  if (size.x == allowed) {
    EXPECT_EQ(big.load_report().warnings.size(), allowed < 16384 ? 1u : 0u);
  } else {
    EXPECT_LT(size.x, allowed);
    EXPECT_EQ(allowed % size.x, 0) << "halved";
    EXPECT_THAT(big.load_report().warnings,
                ::testing::Contains(::testing::HasSubstr("is more than this context can hold (its proxy texture refused it); it is downscaled to " +
                                                         std::to_string(size.x) + "x" + std::to_string(size.y))));
  }
  EXPECT_GE(assets::psnr(reference, render(big)), 35.0) << "the 64x64 texture of the same quadrants";
}

}  // namespace
}  // namespace atrium
