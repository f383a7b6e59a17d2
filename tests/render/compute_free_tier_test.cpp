// The compute-free tier (--no-compute; render/storage_free.hpp): every mode
// draws there what it draws on the full tier, on the built-in scene and on the
// real Sponza, from every view, and with MSAA and shadow maps; the programs it
// compiles declare no storage buffer and are no compute shaders, so what runs
// here would run where neither exists; and what needs them (the counting debug
// views) says so in one line and is not offered.
#include <algorithm>
#include <filesystem>
#include <string>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/limits.hpp"
#include "render/gpu_assets.hpp"
#include "render/techniques/technique.hpp"
#include "support/gl_test.hpp"
#include "support/offered_views.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using ComputeFreeTier = testing::GlTest;
using testing::kSize;

constexpr double kMinimumPsnr = 40.0;
const fs::path kSponza = fs::path(ATRIUM_TESTDATA_DIR) / "scenes/sponza-crytek/Sponza.gltf";

WorldOptions tier_options(const std::string& scene, bool compute_free) {
  WorldOptions options{.scene = scene, .lights = 64u, .mode = "forward", .size = kSize};
  options.technique_options.compute_free = compute_free;
  options.system_options["fireflies"] = 12;  // a system's own pass draws on the tier too
  return options;
}

// What `world` compiled for the tier: no storage blocks, no compute stage.
void expect_storage_free_programs(World& world) {
  std::size_t tier_programs = 0;
  world.registry().resource<render::GpuAssets>().shaders().for_each(
      [&](const std::vector<std::string>& files, const std::vector<gfx::ShaderDefine>& defines, const gfx::ShaderProgram& program) {
        if (std::find_if(defines.begin(), defines.end(), [](const gfx::ShaderDefine& d) { return d.name == "NO_STORAGE_BUFFERS"; }) ==
            defines.end()) {
          return;
        }
        ++tier_programs;
        GLint blocks = -1;
        glGetProgramInterfaceiv(program.id(), GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
        EXPECT_EQ(blocks, 0) << files.back() << " reads or writes a storage buffer on the compute-free tier";
        for (const std::string& file : files) EXPECT_FALSE(file.ends_with(".comp")) << file << " is a compute shader";
      });
  EXPECT_GT(tier_programs, 6u);
}

// Every mode, from every view of `scene`, against the same mode on the full tier.
// `views`: the first that many (0: all).
void expect_tier_matches_full(const std::string& scene, int samples = 1, int shadows = 0, int views = 0) {
  WorldOptions full_options = tier_options(scene, false), free_options = tier_options(scene, true);
  full_options.technique_options.msaa = free_options.technique_options.msaa = samples;
  full_options.shadows = free_options.shadows = shadows;
  World full(full_options);
  World free(free_options);
  std::size_t compared = 0;
  const std::vector<std::string> modes = techniques::mode_names(TechniqueOptions{.compute_free = true});
  for (const std::string& mode : modes) {
    full.set_mode(mode);
    free.set_mode(mode);
    const int view_count = views > 0 ? views : static_cast<int>(full.scene().views.size());
    for (int view = 1; view <= view_count; ++view) {
      full.set_view(view);
      free.set_view(view);
      full.frame(0.0);
      free.frame(0.0);
      const double psnr = assets::psnr(full.renderer().read_output(), free.renderer().read_output());
      EXPECT_GE(psnr, kMinimumPsnr) << mode << ", view " << view << ", MSAA " << samples << ", " << shadows << " shadowed lights";
      ++compared;
    }
  }
  EXPECT_EQ(compared, modes.size() * static_cast<std::size_t>(views > 0 ? views : static_cast<int>(full.scene().views.size())));
  expect_storage_free_programs(free);
}

TEST_F(ComputeFreeTier, EveryModeDrawsTheFullTiersPictureOfTheBuiltInScene) { expect_tier_matches_full("atrium"); }

TEST_F(ComputeFreeTier, EveryModeDrawsTheFullTiersPictureOfSponza) {
  if (!fs::exists(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  expect_tier_matches_full(kSponza.string());
}

// Every debug view each mode offers on the tier draws there (what the tier
// cannot draw, it does not offer).
TEST_F(ComputeFreeTier, EveryViewAModeOffersThereDraws) {
  WorldOptions options = tier_options("atrium", true);
  options.lights = 16u;
  options.size = {64, 36};
  World world(options);
  testing::expect_every_offered_view_draws(world);
  expect_storage_free_programs(world);
}

// Two views: the court (the shadows of the arcades) and the gallery.
TEST_F(ComputeFreeTier, EveryModeMatchesTheFullTierWithMsaaAndShadowMaps) { expect_tier_matches_full("atrium", 4, 4, 2); }

TEST_F(ComputeFreeTier, CountingViewsSayTheyNeedImageAtomicsInOneLineAndAreNotOffered) {
  World world(tier_options("atrium", true));
  for (const std::string view : {"heatmap", "fragments"}) {
    world.registry().resource<RendererSettings>().debug_view = view;
    try {
      world.frame(0.0);
      ADD_FAILURE() << view << " ran on the compute-free tier";
    } catch (const gfx::ResourceLimitError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("the debug view " + view + " on the compute-free tier"), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  world.registry().resource<RendererSettings>().debug_view = "";
  world.frame(0.0);
  for (const render::OfferedView& view : world.renderer().offered_views()) {
    EXPECT_NE(view.name, "heatmap") << "a view the tier refuses is not offered";
    EXPECT_NE(view.name, "fragments") << "a view the tier refuses is not offered";
  }
}

// The technique table's column: a mode that needs compute is refused in one
// line naming what the tier lacks, and left out of the tier's mode list.
TEST_F(ComputeFreeTier, ModesThatNeedComputeAreRefusedInOneLineAndNotListed) {
  World world(tier_options("atrium", true));
  const std::vector<std::string> listed = techniques::mode_names(TechniqueOptions{.compute_free = true});
  std::size_t refused = 0;
  for (const techniques::TechniqueInfo& info : techniques::technique_table()) {
    if (!info.needs.compute) continue;
    ++refused;
    EXPECT_EQ(std::count(listed.begin(), listed.end(), std::string(info.name)), 0) << info.name;
    world.set_mode(std::string(info.name));
    try {
      world.frame(0.0);
      ADD_FAILURE() << info.name << " ran on the compute-free tier";
    } catch (const gfx::ResourceLimitError& e) {
      EXPECT_EQ(std::string(e.what()), std::string(info.name) + " needs compute shaders and storage buffers, which this context's tier "
                                                               "(OpenGL 4.1, ES 3.0, WebGL2) lacks; use another mode");
    }
  }
  EXPECT_GE(refused, 1u) << "visibility-buffer needs compute";
  world.set_mode("clustered-deferred");
  world.frame(0.0);
}

}  // namespace
}  // namespace atrium
