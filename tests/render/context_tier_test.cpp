// Atrium on contexts without compute shaders or storage buffers: OpenGL ES 3.0
// (WebGL2's feature set) and OpenGL 4.1 core (where macOS stops), which
// llvmpipe gives when Mesa's version and extension overrides hold it back
// (tests/CMakeLists.txt sets them). On such a context the world runs the
// compute-free tier by itself, every program compiles in that context's GLSL
// (gfx/glsl_dialect.hpp), entry points it lacks are emulated
// (gfx/gl_emulation.hpp), and every mode draws what the full tier draws.
//
// The references come from the full tier on an OpenGL 4.5 context, in another
// run of this program (ctest fixture context_tier_references), written to
// $ATRIUM_TIER_REFERENCES: TierReferences.* runs where the context has the
// full tier, ContextTier.* where it does not.
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"
#include "render/techniques/technique.hpp"
#include "support/gl_test.hpp"
#include "support/offered_views.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;
constexpr double kMinimumPsnr = 40.0;
const fs::path kSponza = fs::path(ATRIUM_TESTDATA_DIR) / "scenes/sponza-crytek/Sponza.gltf";

fs::path references() {
  const char* dir = std::getenv("ATRIUM_TIER_REFERENCES");
  return dir ? fs::path(dir) : fs::path();
}

// The pictures compared: every mode from every view, with a system's own pass
// (fireflies) and, on the built-in scene, shadow maps.
struct Case {
  std::string tag;
  std::string scene;
  int shadows;
};
const Case kBuiltIn{"builtin", "atrium", 4};
const Case kSponzaCase{"sponza", kSponza.string(), 0};

WorldOptions options_for(const Case& c) {
  WorldOptions options{.scene = c.scene, .lights = 64u, .mode = "forward", .size = kSize};
  options.shadows = c.shadows;
  options.system_options["fireflies"] = 12;
  return options;
}

fs::path reference_path(const Case& c, std::string_view mode, int view) {
  return references() / (c.tag + "-" + std::string(mode) + "-" + std::to_string(view) + ".png");
}

// Calls draw(mode, view, image) for every mode from every view of `c`.
template <typename Draw>
void each_picture(const Case& c, Draw draw) {
  World world(options_for(c));
  // The modes both tiers run (the compute-free tier refuses those that need compute).
  for (const std::string& mode : techniques::mode_names(TechniqueOptions{.compute_free = true})) {
    world.set_mode(mode);
    for (int view = 1; view <= static_cast<int>(world.scene().views.size()); ++view) {
      world.set_view(view);
      world.frame(0.0);
      draw(mode, view, world.renderer().read_output());
    }
  }
}

class TierReferences : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (references().empty()) GTEST_SKIP() << "ATRIUM_TIER_REFERENCES is not set";
    if (!gfx::gl_features().full_tier()) GTEST_SKIP() << "this context cannot draw the full tier";
    fs::create_directories(references());
  }
  static void write(const Case& c) {
    each_picture(c, [&](std::string_view mode, int view, const assets::Image& image) {
      assets::write_png(reference_path(c, mode, view), image);
    });
  }
};

TEST_F(TierReferences, BuiltInScene) { write(kBuiltIn); }

TEST_F(TierReferences, Sponza) {
  if (!fs::exists(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  write(kSponzaCase);
}

class ContextTier : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (references().empty()) GTEST_SKIP() << "ATRIUM_TIER_REFERENCES is not set";
    if (gfx::gl_features().full_tier()) GTEST_SKIP() << "this context has compute: see tests/CMakeLists.txt";
  }
  static void expect_matches_full_tier(const Case& c) {
    std::size_t compared = 0;
    each_picture(c, [&](std::string_view mode, int view, const assets::Image& image) {
      const fs::path reference = reference_path(c, mode, view);
      ASSERT_TRUE(fs::exists(reference)) << reference << ": the reference run (context_tier_references) did not write it";
      EXPECT_GE(assets::psnr(assets::read_png(reference), image), kMinimumPsnr)
          << mode << ", view " << view << " on " << gfx::gl_features().api_name();
      ++compared;
    });
    EXPECT_GE(compared, techniques::mode_names(TechniqueOptions{.compute_free = true}).size());
  }
};

TEST_F(ContextTier, TheWorldRunsTheComputeFreeTierByItself) {
  const gfx::GlFeatures& gl = gfx::gl_features();
  EXPECT_FALSE(gl.compute_shaders);
  EXPECT_FALSE(gl.storage_buffers);
  EXPECT_EQ(gl.missing_for_full_tier(), "no compute shaders, no storage buffers");
  WorldOptions options = options_for(kBuiltIn);
  ASSERT_FALSE(options.technique_options.compute_free);
  World world(options);
  world.frame(0.0);
  EXPECT_TRUE(world.registry().resource<RendererSettings>().technique_options.compute_free);
}

TEST_F(ContextTier, EveryModeDrawsTheFullTiersPictureOfTheBuiltInScene) { expect_matches_full_tier(kBuiltIn); }

TEST_F(ContextTier, EveryModeDrawsTheFullTiersPictureOfSponza) {
  if (!fs::exists(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  expect_matches_full_tier(kSponzaCase);
}

// What this context cannot draw is refused in one line before any program
// for it is compiled (its GLSL would not compile here).
TEST_F(ContextTier, RefusesWhatItCannotDrawInOneLine) {
  const auto refusal = [](WorldOptions options) -> std::string {
    try {
      World world(options);
      world.frame(0.0);
    } catch (const gfx::ResourceLimitError& e) {
      return e.what();
    }
    return "(drawn)";
  };
  WorldOptions counting = options_for(kBuiltIn);
  counting.debug_view = "heatmap";
  const std::string heatmap = refusal(counting);
  EXPECT_NE(heatmap.find("the debug view heatmap on the compute-free tier"), std::string::npos) << heatmap;
  EXPECT_EQ(heatmap.find('\n'), std::string::npos) << heatmap;
  if (!gfx::gl_features().multisample_textures) {
    WorldOptions msaa = options_for(kBuiltIn);
    msaa.technique_options.msaa = 4;
    const std::string samples = refusal(msaa);
    EXPECT_NE(samples.find("MSAA with 4 samples: this context allows at most 1"), std::string::npos) << samples;
  }
}

// Every debug view a mode offers compiles in this context's GLSL and draws.
TEST_F(ContextTier, EveryViewAModeOffersDraws) {
  WorldOptions options = options_for(kBuiltIn);
  options.size = {64, 36};
  World world(options);
  testing::expect_every_offered_view_draws(world);
}

}  // namespace
}  // namespace atrium
