// Texture upload limits: a texture wider or taller than the context allows (or
// than --max-texture-size) is downscaled with one warning naming it, and draws
// the picture that a small texture of the same content draws. The data comes
// from tests/data/make_big_texture.py at build time.
#include <gmock/gmock.h>

#include "app/world.hpp"
#include "render/gpu_assets.hpp"
#include "assets/image.hpp"
#include "gfx/limits.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using TextureLimits = testing::GlTest;

const std::string kBig = std::string(ATRIUM_BIG_TEXTURE_DIR) + "/big-texture.gltf";
const std::string kSmall = std::string(ATRIUM_BIG_TEXTURE_DIR) + "/small-texture.gltf";

WorldOptions options(const std::string& scene, int max_texture_size = 0) {
  return {.scene = scene, .lights = 0u, .size = {160, 90}, .max_texture_size = max_texture_size};
}

glm::ivec2 uploaded_size(World& world) {
  const GLuint texture = world.registry().resource<render::GpuAssets>().texture(assets::TextureHandle{0});
  glm::ivec2 size{0};
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &size.x);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &size.y);
  return size;
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

TEST_F(TextureLimits, A16384TextureLoadsAtWhatTheContextAllows) {
  World small(options(kSmall));
  const assets::Image reference = render(small);
  World big(options(kBig));
  const int limit = gfx::max_texture_size();
  EXPECT_EQ(uploaded_size(big), glm::ivec2(std::min(limit, 16384)));
  EXPECT_EQ(big.load_report().warnings.size(), limit < 16384 ? 1u : 0u);
  EXPECT_GE(assets::psnr(reference, render(big)), 35.0) << "the 64x64 texture of the same quadrants";
}

}  // namespace
}  // namespace atrium
