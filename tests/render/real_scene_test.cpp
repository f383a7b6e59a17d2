// scenes/sponza.json opened as a user who fetched Sponza opens it (the scene
// file from the repository, the real Crytek Sponza from ../shared linked where
// scripts/fetch-scenes.sh puts it): every texture loads, every view shows depth,
// every mode draws forward's picture, and no camera pressed against, inside or
// just behind a wall (here and in the built-in scene) shades many more fragments
// than the stored views or stalls the frame.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "render/gpu_assets.hpp"
#include "assets/image.hpp"
#include "assets/scene_file.hpp"
#include "components/frame_resources.hpp"
#include "gfx/limits.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "systems/camera.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;
const fs::path kSponza = fs::path(ATRIUM_TESTDATA_DIR) / "scenes/sponza-crytek";

// A folder laid out like the repository after `scripts/fetch-scenes.sh sponza`.
class SponzaScene : public testing::GlTest {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("atrium_sponza_" + std::to_string(::getpid()));
    fs::create_directories(root_ / "scenes");
    fs::create_directories(root_ / "assets/sponza");
    fs::copy_file(fs::path(ATRIUM_SOURCE_DIR) / "scenes/sponza.json", root_ / "scenes/sponza.json");
    if (fs::is_directory(kSponza)) fs::create_directory_symlink(kSponza, root_ / "assets/sponza/glTF");
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  void SetUp() override {
    testing::GlTest::SetUp();
    if (!fs::is_directory(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  }

  static WorldOptions options(const std::string& mode = "forward") {
    WorldOptions o;
    o.scene = (root_ / "scenes/sponza.json").string();
    o.mode = mode;
    o.size = kSize;
    return o;
  }

  static fs::path root_;
};
fs::path SponzaScene::root_;

// Fragment shader invocations of the latest frame, every pass together: what a
// frame costs the rasteriser, counted exactly by the driver (pipeline statistics).
std::uint64_t frame_fragments(World& world) {
  world.frame(0.0);
  (void)world.renderer().read_output();
  std::uint64_t fragments = 0;
  for (const gfx::PassTime& pass : world.renderer().timer().latest()) fragments += pass.fragments;
  return fragments;
}

TEST_F(SponzaScene, LoadsEveryTexture) {
  World world(options());
  EXPECT_EQ(world.scene().views.size(), 5u);
  EXPECT_EQ(world.load_report().images, 69u);
  for (const std::string& warning : world.load_report().warnings) {
    EXPECT_EQ(warning.find("cannot be decoded"), std::string::npos) << warning;
    EXPECT_EQ(warning.find("neutral default"), std::string::npos) << warning;
  }
}

TEST_F(SponzaScene, EveryViewLooksIntoTheAtriumNotAtAWall) {
  World world(options());
  for (int view = 1; view <= 5; ++view) {
    world.set_view(view);
    world.frame(0.0);
    const assets::Image image = world.renderer().read_output();
    assets::write_png("sponza_view" + std::to_string(view) + ".png", image);
    std::vector<float> depth = world.renderer().read_view_depth();
    std::erase_if(depth, [](float d) { return !std::isfinite(d); });
    ASSERT_GT(depth.size(), static_cast<std::size_t>(kSize.x * kSize.y) * 8 / 10) << "view " << view << " sees the sky mostly";
    std::sort(depth.begin(), depth.end());
    const float near = depth[depth.size() / 10], far = depth[depth.size() * 9 / 10];
    // A wall filling the frame is at one depth; the atrium spans metres to tens of metres.
    EXPECT_GT(far / near, 2.5f) << "view " << view << ": depths from " << near << " to " << far << " m";
    double luma = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) luma += assets::luma(image, x, y);
    }
    EXPECT_GT(luma / (kSize.x * kSize.y), 0.15) << "view " << view << " is lit";
  }
}

TEST_F(SponzaScene, EveryModeDrawsForwardsPictureFromEveryView) {
  World world(options());
  testing::compare_every_mode_with_forward(world, [](const std::string& mode, int view, const assets::Image& reference,
                                                      const assets::Image& image) {
    EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << mode << " view " << view;
  });
}

// The compute stage (--lighting-stage compute) on the real scene: its alpha-tested
// foliage, normal maps and blended surfaces light as in the fragment stage.
TEST_F(SponzaScene, TheComputeStageDrawsTheFragmentStagesPicture) {
  World world(options());
  auto& stage = world.registry().resource<RendererSettings>().technique_options.lighting_stage;
  for (int view = 1; view <= 5; ++view) {
    world.set_view(view);
    world.set_mode("forward");
    stage = LightingStage::Fragment;
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    for (const char* mode : {"deferred-radius", "tiled-deferred", "clustered-deferred"}) {
      world.set_mode(mode);
      stage = LightingStage::Fragment;
      world.frame(0.0);
      const assets::Image fragment = world.renderer().read_output();
      stage = LightingStage::Compute;
      world.frame(0.0);
      const assets::Image compute = world.renderer().read_output();
      EXPECT_EQ(world.renderer().stats().lighting_stage, LightingStage::Compute);
      EXPECT_GE(assets::psnr(fragment, compute), 50.0) << mode << " view " << view;
      EXPECT_GE(assets::psnr(reference, compute), kMinimumPsnr) << mode << " view " << view;
    }
  }
}

// The stored views shade within a small factor of each other; against, inside
// and just behind walls, a frame shades no more fragments than the costliest
// stored view, within a small factor, and finishes: Sponza's view 1 once
// took 80 s a frame where the others took 30 ms (llvmpipe's anisotropic filter
// on a leaf seen edge-on at the camera; see SoftwareRenderersSampleTrilinearly).
// Fragment counts are exact, so the comparison holds on a loaded machine; the
// time limit only catches a frame that never ends, two orders above a slow one.
void expect_no_camera_costs_much_more(World& world, const std::vector<assets::NamedView>& awkward, const std::string& scene) {
  ASSERT_TRUE(world.renderer().timer().counts_fragments()) << "the driver does not count fragments";
  std::uint64_t most = 0, least = UINT64_MAX;
  for (int view = 1; view <= static_cast<int>(world.scene().views.size()); ++view) {
    world.set_view(view);
    const std::uint64_t fragments = frame_fragments(world);
    most = std::max(most, fragments);
    least = std::min(least, fragments);
  }
  ASSERT_GT(least, 0u);
  // Sponza's five views shade 12 to 25 fragments per pixel at 160x90 (tiny
  // triangles shade whole 2x2 quads): none is a costly outlier.
  EXPECT_LT(most, 3 * least) << scene << ": the stored views shade " << least << " to " << most << " fragments";
  constexpr double kFreezeSeconds = 20.0;
  for (const assets::NamedView& camera : awkward) {
    apply_view(world.registry(), camera);
    // Planes fitted afresh, as when the program starts there (--camera).
    world.registry().resource<ViewState>() = ViewState{};
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t fragments = frame_fragments(world);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(fragments, 2 * most) << scene << " " << camera.name << ": " << fragments << " fragments against " << most
                                   << " for the costliest stored view";
    EXPECT_LT(seconds, kFreezeSeconds) << scene << " " << camera.name;
  }
}

// The sampler every mipmapped material slot uses filters trilinearly on a
// software renderer, where anisotropic filtering costs seconds per frame.
TEST_F(SponzaScene, SoftwareRenderersSampleTrilinearly) {
  World world(options());
  if (!gfx::is_software_renderer()) GTEST_SKIP() << "a hardware renderer filters anisotropically";
  GLfloat anisotropy = 0.0f;
  glGetSamplerParameterfv(world.registry().resource<render::GpuAssets>().sampler(assets::SamplerDesc{}), GL_TEXTURE_MAX_ANISOTROPY,
                          &anisotropy);
  EXPECT_EQ(anisotropy, 1.0f);
}

TEST_F(SponzaScene, NoCameraCostsMuchMoreThanTheStoredViews) {
  World world(options("deferred"));
  expect_no_camera_costs_much_more(world,
                                   {{"against the west wall", glm::vec3(-11.3f, 1.7f, -0.25f), -90.0f, 0.0f},
                                    // The first nave view, guessed before Sponza was ever opened: behind
                                    // the west wall, a leaf of the plants edge-on at the camera (80 s a
                                    // frame with llvmpipe's anisotropic filter; the exact place matters).
                                    {"the old nave view", glm::vec3(-12.9862709f, 0.48217988f, -0.309263229f), 90.0f, 3.0f},
                                    {"in the plants by the first column", glm::vec3(-5.0f, 0.6f, -2.0f), 90.0f, -10.0f},
                                    {"inside a column", glm::vec3(-2.0f, 1.0f, -2.2f), 0.0f, 0.0f},
                                    {"just behind the west wall", glm::vec3(-11.6f, 1.7f, -0.25f), 90.0f, 0.0f},
                                    {"in the gallery floor", glm::vec3(-3.5f, 4.1f, 3.1f), 90.0f, -20.0f}},
                                   "Sponza");
}

using BuiltinScene = testing::GlTest;

TEST_F(BuiltinScene, NoCameraCostsMuchMoreThanTheStoredViews) {
  World world({.scene = "atrium", .mode = "deferred", .size = kSize});
  expect_no_camera_costs_much_more(world,
                                   {{"against the west wall", glm::vec3(-16.98f, 1.7f, 0.0f), -90.0f, 0.0f},
                                    {"inside a column", glm::vec3(-15.0f, 2.0f, 10.0f), 90.0f, 0.0f},
                                    {"just behind the west wall", glm::vec3(-17.05f, 1.7f, 0.0f), 90.0f, 0.0f},
                                    {"in a banner", glm::vec3(-10.5f, 9.0f, 9.55f), 0.0f, 0.0f}},
                                   "the built-in scene");
}

}  // namespace
}  // namespace atrium
