// scenes/sponza.json opened as a user who fetched Sponza opens it (the scene
// file from the repository, the real Crytek Sponza from ../shared linked where
// scripts/fetch-scenes.sh puts it): every texture loads, every view shows depth,
// every mode draws forward's picture, and no view (nor a camera pressed against,
// inside or just behind a wall, here and in the built-in scene) costs much more
// than the others.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/scene_file.hpp"
#include "components/frame_resources.hpp"
#include "support/gl_test.hpp"
#include "systems/camera.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

constexpr glm::ivec2 kSize{160, 90};
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

// Seconds for one frame, the fastest of three (a loaded machine only adds time).
double frame_seconds(World& world) {
  double best = 1e30;
  for (int i = 0; i < 3; ++i) {
    const auto start = std::chrono::steady_clock::now();
    world.frame(0.0);
    (void)world.renderer().read_output();  // waits for the frame
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
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
  for (int view = 1; view <= 5; ++view) {
    world.set_view(view);
    world.set_mode("forward");
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    for (const std::string& mode : lighting::mode_names()) {
      if (mode == "forward") continue;
      world.set_mode(mode);
      world.frame(0.0);
      EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), 40.0) << mode << " view " << view;
    }
  }
}

// Against, inside and just behind walls, the frame costs what the stored views
// cost within a small factor: Sponza's view 1 once took 80 s a frame (llvmpipe's
// anisotropic filter on a leaf seen edge-on at the camera) where the others took 30 ms.
void expect_no_camera_costs_much_more(World& world, const std::vector<assets::NamedView>& awkward, const std::string& scene) {
  std::vector<double> views;
  for (int view = 1; view <= static_cast<int>(world.scene().views.size()); ++view) {
    world.set_view(view);
    views.push_back(frame_seconds(world));
  }
  const double typical = median(views);
  EXPECT_LT(*std::max_element(views.begin(), views.end()), 4.0 * typical) << scene << ": a stored view costs much more than the others";
  for (const assets::NamedView& camera : awkward) {
    apply_view(world.registry(), camera);
    // Planes fitted afresh, as when the program starts there (--camera).
    world.registry().resource<ViewState>() = ViewState{};
    const double seconds = frame_seconds(world);
    EXPECT_LT(seconds, 4.0 * typical) << scene << " " << camera.name << ": " << seconds * 1000 << " ms against " << typical * 1000
                                      << " ms for the median stored view";
  }
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
  World world({"atrium", std::nullopt, "deferred", 1, kSize});
  expect_no_camera_costs_much_more(world,
                                   {{"against the west wall", glm::vec3(-16.98f, 1.7f, 0.0f), -90.0f, 0.0f},
                                    {"inside a column", glm::vec3(-15.0f, 2.0f, 10.0f), 90.0f, 0.0f},
                                    {"just behind the west wall", glm::vec3(-17.05f, 1.7f, 0.0f), 90.0f, 0.0f},
                                    {"in a banner", glm::vec3(-10.5f, 9.0f, 9.55f), 0.0f, 0.0f}},
                                   "the built-in scene");
}

}  // namespace
}  // namespace atrium
