// The compute lighting stage (--lighting-stage compute): every mode draws the
// picture it draws in the fragment stage and forward's picture, with each
// G-buffer layout, split light sums, shadows, the fireflies and the debug views
// it offers, with MSAA, and with many lights summed in runs; the full-screen passes really run as compute (no fragment shaded);
// combinations it cannot run are refused in one line; auto takes the stage
// measured faster on this renderer; the image units the GLSL names are the
// C++ constants.
#include <filesystem>
#include <fstream>
#include <set>

#include <gmock/gmock.h>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/limits.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"

namespace atrium {
namespace {

using testing::kSize;

// The modes whose lighting is one full-screen pass: the compute stage runs it.
const std::set<std::string> kFullScreenLighting{"deferred", "deferred-radius", "tiled-deferred", "clustered-deferred"};
// The stages agree to rounding: llvmpipe gives identical pictures; a GPU may
// order floating-point work differently.
constexpr double kStagesAgreeDb = 50.0;

void set_stage(World& world, LightingStage stage) {
  world.registry().resource<RendererSettings>().technique_options.lighting_stage = stage;
}

assets::Image draw(World& world, LightingStage stage) {
  set_stage(world, stage);
  world.frame(0.0);
  return world.renderer().read_output();
}

// The fragments a pass of the latest frame shaded (pipeline statistics).
std::uint64_t fragments_of(World& world, const std::string& pass) {
  world.renderer().settle();
  for (const gfx::PassTime& time : world.renderer().timer().latest()) {
    if (time.name == pass) return time.fragments;
  }
  return 0;
}

class ComputeStage : public testing::GlTest,
                     public ::testing::WithParamInterface<std::tuple<std::string, GBufferLayout>> {};

// Views 1 (the court, open sky) and 3 (the lamps, glass and many lights close
// by); every view against forward is the fragment stage's test, and the
// stages agree pixel for pixel there.
TEST_P(ComputeStage, DrawsTheFragmentStagesAndForwardsPicture) {
  const auto& [mode, layout] = GetParam();
  World world({.scene = "atrium", .mode = mode, .size = kSize, .technique_options = testing::with_layout(layout)});
  for (const int view : {1, 3}) {
    world.set_view(view);
    world.set_mode("forward");
    const assets::Image reference = draw(world, LightingStage::Fragment);
    world.set_mode(mode);
    const assets::Image fragment = draw(world, LightingStage::Fragment);
    const assets::Image compute = draw(world, LightingStage::Compute);
    EXPECT_EQ(world.renderer().stats().lighting_stage, LightingStage::Compute);
    assets::write_png("stage_" + testing::test_name(mode, layout) + "_view" + std::to_string(view) + ".png", compute);
    EXPECT_GE(assets::psnr(fragment, compute), kStagesAgreeDb) << mode << " view " << view;
    EXPECT_GE(assets::psnr(reference, compute), kMinimumPsnr) << mode << " view " << view;
  }
  if (!world.renderer().timer().counts_fragments()) return;
  EXPECT_EQ(fragments_of(world, "tonemap"), 0u) << "the tone map ran as a fragment pass";
  if (kFullScreenLighting.contains(mode)) EXPECT_EQ(fragments_of(world, "lighting"), 0u) << "the lighting ran as a fragment pass";
}

INSTANTIATE_TEST_SUITE_P(Modes, ComputeStage, ::testing::ValuesIn(testing::mode_layouts()),
                         [](const auto& info) { return testing::test_name(std::get<0>(info.param), std::get<1>(info.param)); });

using ComputeStageWith = testing::GlTest;

TEST_F(ComputeStageWith, SplitLightSumsAsTheFragmentStageWritesThem) {
  for (const std::string& mode : kFullScreenLighting) {
    World world({.scene = "atrium", .mode = mode, .view = 3, .size = kSize});
    world.registry().resource<RendererSettings>().technique_options.split_lighting = true;
    std::vector<std::vector<glm::vec4>> sums[2];
    for (const LightingStage stage : {LightingStage::Fragment, LightingStage::Compute}) {
      (void)draw(world, stage);
      for (const auto target : {render::MeshRenderer::HdrTarget::Color, render::MeshRenderer::HdrTarget::DiffuseLight, render::MeshRenderer::HdrTarget::SpecularLight}) {
        sums[stage == LightingStage::Compute].push_back(world.renderer().read_hdr(target));
      }
    }
    for (std::size_t target = 0; target < 3; ++target) {
      const auto& a = sums[0][target];
      const auto& b = sums[1][target];
      ASSERT_EQ(a.size(), b.size());
      double largest = 0, total = 0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        largest = std::max(largest, static_cast<double>(glm::length(a[i] - b[i])));
        total += glm::length(glm::vec3(a[i]));
      }
      EXPECT_GT(total, 0.0) << mode << " target " << target << " is black";
      EXPECT_LT(largest, 1e-3) << mode << " target " << target;
    }
  }
}

// With MSAA the compute stage finds the edges itself (no stencil marks, no
// fragment pass) and shades their other samples spread over the work group:
// the fragment stage's picture and its light evaluations, sample for sample,
// less llvmpipe's seam: it clips the full-screen triangle to the viewport into
// two triangles, and with MSAA the pixels on their shared diagonal run the
// fragment stage's passes twice (in the heatmap, 83 pixels on that diagonal
// count more, 0.4% of the total).
TEST_F(ComputeStageWith, MsaaShadingTheEdgesSamplesAsTheFragmentStageDoes) {
  TechniqueOptions msaa;
  msaa.msaa = 4;
  World world({.scene = "atrium", .mode = "forward", .size = kSize, .technique_options = msaa});
  const assets::Image reference = draw(world, LightingStage::Fragment);
  auto& settings = world.registry().resource<RendererSettings>();
  for (const std::string& mode : kFullScreenLighting) {
    world.set_mode(mode);
    const assets::Image fragment = draw(world, LightingStage::Fragment);
    const std::uint64_t geometry_fragments = fragments_of(world, "geometry");
    const assets::Image compute = draw(world, LightingStage::Compute);
    assets::write_png("stage_msaa_" + testing::test_name(mode, GBufferLayout::Full) + ".png", compute);
    EXPECT_GE(assets::psnr(fragment, compute), kStagesAgreeDb) << mode;
    EXPECT_GE(assets::psnr(reference, compute), kMinimumPsnr) << mode;
    if (world.renderer().timer().counts_fragments()) {
      EXPECT_EQ(fragments_of(world, "lighting"), 0u) << mode;
      // The fragment stage's geometry pass ends with the edge-marking pass, a
      // full-screen pass whose fragments mostly discard; the compute stage marks
      // edges in compute. llvmpipe counts every pixel of that pass, but the
      // pipeline statistics leave a driver free to skip invocations (or run
      // more) where the picture does not change (lavapipe, under zink, counts
      // about 2,900 of 14,400, near the number of edge pixels): fewer is what
      // holds on every driver.
      EXPECT_LT(fragments_of(world, "geometry"), geometry_fragments) << mode;
    }
    settings.debug_view = "heatmap";
    (void)draw(world, LightingStage::Fragment);
    world.renderer().settle();
    const double counted_fragment = world.renderer().stats().light_evaluations_per_pixel;
    (void)draw(world, LightingStage::Compute);
    world.renderer().settle();
    const double counted_compute = world.renderer().stats().light_evaluations_per_pixel;
    EXPECT_LE(counted_compute, counted_fragment) << mode;
    EXPECT_GE(counted_compute, 0.99 * counted_fragment) << mode;
    settings.debug_view.clear();
  }
}

// 20,000 lights are two runs of the deferred modes' pass over every light
// (lights_per_run: 16,384 at most): the later run adds to the first, in both
// stages, and the sum is forward's picture.
TEST_F(ComputeStageWith, ManyLightsSummedInRunsDrawForwardsPicture) {
  constexpr std::uint32_t kLights = 20000;
  constexpr glm::ivec2 kSmall{48, 27};
  WorldOptions options{.scene = "atrium", .lights = kLights, .mode = "forward", .view = 3, .size = kSmall, .light_radius = 1.0f};
  World reference_world(options);
  reference_world.frame(0.0);
  const assets::Image reference = reference_world.renderer().read_output();
  for (const std::string mode : {"deferred", "deferred-radius"}) {
    options.mode = mode;
    World world(options);
    world.registry().resource<RendererSettings>().technique_options.split_lighting = true;
    for (const LightingStage stage : {LightingStage::Fragment, LightingStage::Compute}) {
      ASSERT_LT(lighting::lights_per_run(kSmall, 1, stage), kLights) << "two runs or more";
      const assets::Image image = draw(world, stage);
      EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << mode << ", " << lighting::lighting_stage_name(stage);
    }
  }
}

// A run sums at most 2^33 light evaluations in compute and 2^28 as fragments
// (about 20 ms each on an H200), and never more than 16,384 lights; with MSAA
// every sample may be shaded (a frame of edges), so each counts.
TEST(LightRuns, KeepEachDispatchShort) {
  using lighting::lights_per_run;
  EXPECT_EQ(lights_per_run({1920, 1080}, 1, LightingStage::Compute), 4142u);
  EXPECT_EQ(lights_per_run({1920, 1080}, 1, LightingStage::Fragment), 129u);
  EXPECT_EQ(lights_per_run({1920, 1080}, 4, LightingStage::Compute), 1035u);
  EXPECT_EQ(lights_per_run({1920, 1080}, 4, LightingStage::Fragment), 32u);
  EXPECT_EQ(lights_per_run({320, 180}, 0, LightingStage::Compute), lighting::kMostLightsPerRun) << "0: no MSAA";
  EXPECT_EQ(lights_per_run({320, 180}, 1, LightingStage::Fragment), 4660u);
  EXPECT_EQ(lights_per_run({1 << 20, 1 << 20}, 1, LightingStage::Fragment), 1u) << "always at least one light";
  EXPECT_EQ(lights_per_run({0, 0}, 1, LightingStage::Compute), lighting::kMostLightsPerRun);
}

TEST_F(ComputeStageWith, ShadowsFirefliesAndTheOfferedDebugViews) {
  // Smaller than kSize: each mode shows each of its views twice.
  WorldOptions options{.scene = "atrium", .mode = "forward", .view = 3, .size = {64, 36}, .shadows = 4};
  options.system_options["fireflies"] = 64;
  World world(options);
  const assets::Image reference = draw(world, LightingStage::Fragment);
  for (const std::string& mode : kFullScreenLighting) {
    world.set_mode(mode);
    const assets::Image fragment = draw(world, LightingStage::Fragment);
    EXPECT_GE(assets::psnr(fragment, draw(world, LightingStage::Compute)), kStagesAgreeDb) << mode;
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode;
    // Every view the mode offers shows the same in both stages, the counting ones with the same counts.
    const std::vector<render::OfferedView> offered = world.renderer().offered_views();  // each frame remakes the list
    for (const render::OfferedView& view : offered) {
      auto& settings = world.registry().resource<RendererSettings>();
      settings.debug_view = view.name;
      const assets::Image shown_fragment = draw(world, LightingStage::Fragment);
      world.renderer().settle();
      const double counted_fragment = world.renderer().stats().light_evaluations_per_pixel;
      const assets::Image shown_compute = draw(world, LightingStage::Compute);
      world.renderer().settle();
      EXPECT_GE(assets::psnr(shown_fragment, shown_compute), kStagesAgreeDb) << mode << " " << view.name;
      if (view.name == "heatmap") EXPECT_DOUBLE_EQ(counted_fragment, world.renderer().stats().light_evaluations_per_pixel) << mode;
      settings.debug_view.clear();
    }
  }
}

using LightingStages = testing::GlTest;

std::string refusal(const TechniqueOptions& options) {
  try {
    (void)lighting::resolve_lighting_stage(options);
  } catch (const gfx::ResourceLimitError& e) {
    return e.what();
  }
  return "(no refusal)";
}

TEST_F(LightingStages, RefuseWhatTheComputeStageCannotRunInOneLine) {
  EXPECT_EQ(refusal({.compute_free = true, .lighting_stage = LightingStage::Compute}),
            "--lighting-stage compute needs compute shaders and storage images, which the compute-free tier does not use; use "
            "--lighting-stage fragment or auto there");
  // Auto never refuses: it falls back to the fragment stage.
  EXPECT_EQ(lighting::resolve_lighting_stage({.compute_free = true}), LightingStage::Fragment);
  // On a software renderer the fragment stage measured faster (docs/benchmarks.md); on a GPU compute reaches every core,
  // with MSAA too.
  const LightingStage measured_faster = gfx::is_software_renderer() ? LightingStage::Fragment : LightingStage::Compute;
  EXPECT_EQ(lighting::resolve_lighting_stage({}), measured_faster);
  EXPECT_EQ(lighting::resolve_lighting_stage({.msaa = 4}), measured_faster);
}

TEST_F(LightingStages, ImageUnitsInTheShadersAreTheCppConstants) {
  World world({.scene = "atrium", .mode = "deferred", .size = {32, 18}});
  world.registry().resource<RendererSettings>().technique_options.split_lighting = true;
  (void)draw(world, LightingStage::Compute);
  auto& shaders = world.registry().resource<render::GpuAssets>().shaders();
  auto unit = [](gfx::ShaderProgram& program, const char* name) {
    GLint value = -1;
    glGetUniformiv(program.id(), glGetUniformLocation(program.id(), name), &value);
    return value;
  };
  gfx::ShaderProgram& lighting = shaders.get({"deferred/lighting.comp"});
  EXPECT_EQ(unit(lighting, "u_lit_color"), static_cast<GLint>(render::kLitColorImageUnit));
  EXPECT_EQ(unit(lighting, "u_lit_diffuse"), static_cast<GLint>(render::kDiffuseLightImageUnit));
  EXPECT_EQ(unit(lighting, "u_lit_specular"), static_cast<GLint>(render::kSpecularLightImageUnit));
  EXPECT_EQ(unit(shaders.get({"post/tonemap.comp"}), "u_display"), static_cast<GLint>(render::kDisplayImageUnit));
}

TEST_F(LightingStages, ASceneFileChoosesTheStageAndTheCommandLineWins) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / ("atrium_stage_" + std::to_string(::getpid()) + ".json");
  auto write = [&](const std::string& stage) {
    std::ofstream(file) << R"({"models": [{"builtin": "atrium"}], "lighting_stage": ")" << stage << R"("})";
  };
  write("compute");
  {
    World world({.scene = file.string(), .size = {32, 18}});
    EXPECT_EQ(world.registry().resource<RendererSettings>().technique_options.lighting_stage, LightingStage::Compute);
    World overridden({.scene = file.string(), .size = {32, 18}, .lighting_stage = LightingStage::Fragment});
    EXPECT_EQ(overridden.registry().resource<RendererSettings>().technique_options.lighting_stage, LightingStage::Fragment);
  }
  write("vertex");
  try {
    World world({.scene = file.string(), .size = {32, 18}});
    ADD_FAILURE() << "an unknown stage loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": /lighting_stage: unknown lighting stage 'vertex' (stages: auto, fragment, compute)");
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace atrium
