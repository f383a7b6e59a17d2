// Mirrored models as Blender writes them (tests/data/model-tools/mirror-f.*,
// made by blender_mirrored.py): a single-sided, normal-mapped letter F whose
// object is scaled by -1 on X. glTF says a negative determinant turns the
// winding, so its faces stay front faces; seen from the front, under lights on
// the mirror plane, every mode draws the picture of the unmirrored model
// mirrored in image space, from the glTF and FBX (node scale) and OBJ
// (baked) files alike, each against its format's unmirrored export, with and
// without shadows, normal-mapped.
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/scene_file.hpp"
#include "support/gl_test.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;
const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";

using MirroredRender = testing::GlTest;

// The model under a point light, a spot light and a sun, all on the plane
// x = 0 (the mirror's), seen from the front on that plane.
std::unique_ptr<World> make_world(const fs::path& file, int shadows) {
  assets::AssetManager assets;
  assets::LoadReport report;
  assets::SceneDescription scene = assets::load_model_scene(file, assets, 0, report);
  scene.lights = {
      {glm::vec3(0.0f, 0.25f, 0.6f), glm::vec3(1.0f, 0.9f, 0.8f), 0.6f, 3.0f},
      {glm::vec3(0.0f, -0.3f, 0.9f), glm::vec3(0.6f, 0.8f, 1.0f), 1.5f, 3.0f, assets::LightKind::Spot, glm::normalize(glm::vec3(0.0f, 0.3f, -0.9f)),
       0.2f, 0.6f},
      {glm::vec3(0.0f), glm::vec3(1.0f), 0.8f, std::nullopt, assets::LightKind::Directional, glm::normalize(glm::vec3(0.0f, -0.4f, -1.0f))},
  };
  scene.views = {{"front", glm::vec3(0.0f, 0.06f, 1.3f), 0.0f, 0.0f}};
  scene.ambient = glm::vec3(0.0f);
  WorldOptions options;
  options.mode = "forward";
  options.size = kSize;
  options.shadows = shadows;
  return std::make_unique<World>(std::move(assets), std::move(scene), options);
}

assets::Image render(World& world, const std::string& mode) {
  world.set_mode(mode);
  world.frame(0.0);
  return world.renderer().read_output();
}

assets::Image mirrored_in_image_space(assets::Image image) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width / 2; ++x) {
      for (int c = 0; c < 4; ++c) {
        std::swap(image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c],
                  image.rgba[(static_cast<std::size_t>(y) * image.width + (image.width - 1 - x)) * 4 + c]);
      }
    }
  }
  return image;
}

TEST_F(MirroredRender, EveryModeDrawsAMirroredModelAsItsImageMirrored) {
  // Each format against its own unmirrored export: materials map per format.
  for (const char* format : {".glb", ".fbx", ".obj"}) {
    for (const int shadows : {0, 2}) {
      // Each file loaded once, its World switching modes.
      const std::unique_ptr<World> plain_world = make_world(kFixtures / ("mirror-f.plain" + std::string(format)), shadows);
      const std::unique_ptr<World> mirrored_world = make_world(kFixtures / ("mirror-f.mirrored" + std::string(format)), shadows);
      for (const std::string& mode : techniques::mode_names()) {
        const std::string tag = std::string(format + 1) + "_" + mode + (shadows ? "_shadows" : "");
        const assets::Image plain = render(*plain_world, mode);
        const assets::Image expected = mirrored_in_image_space(plain);
        const assets::Image mirrored = render(*mirrored_world, mode);
        assets::write_png("mirror_plain_" + tag + ".png", plain);
        assets::write_png("mirror_mirrored_" + tag + ".png", mirrored);
        // The letter is asymmetric: mirroring the picture changes it.
        EXPECT_LT(assets::psnr(plain, expected), 25.0) << tag;
        EXPECT_GE(assets::psnr(expected, mirrored), kMinimumPsnr) << tag;
      }
    }
  }
}

}  // namespace
}  // namespace atrium
