// Bloom (src/render/post/bloom), the post-process stage's proof: a bright
// spot spreads a glow that falls off with distance and keeps the image's
// energy; every mode draws the forward picture with bloom on, with MSAA, on
// the compute-free tier and with the compute lighting stage; its chain is a
// debug view; off (the default) it adds no pass; and it lives in its own files
// plus one registration line and its option rows.
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/system_options.hpp"
#include "render/gpu_assets.hpp"
#include "render/post/bloom/bloom.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/graph_capture.hpp"
#include "support/modes.hpp"
#include "support/source_mentions.hpp"

namespace atrium {
namespace {

using Bloom = testing::GlTest;
using testing::kSize;


WorldOptions bloom_options(double strength, const std::string& mode = "forward") {
  WorldOptions options{.scene = "atrium", .lights = 24u, .mode = mode, .size = kSize};
  options.system_options["bloom"] = strength;
  return options;
}

bool has_pass(World& world, const std::string& name) {
  for (const render::CompiledPass& pass : world.renderer().graph().passes()) {
    if (pass.name == name && !pass.culled) return true;
  }
  return false;
}

TEST(BloomLevels, FollowTheRadiusAsAFractionOfTheImageHeight) {
  EXPECT_EQ(render::bloom_levels(0.2, 1080), 6);  // a glow of 216 px: levels down to 17 px
  EXPECT_EQ(render::bloom_levels(0.2, 180), 4);   // the same glow at a sixth of the size
  EXPECT_EQ(render::bloom_levels(1.0, 4320), render::kMaxBloomLevels);
  EXPECT_EQ(render::bloom_levels(0.02, 90), 1);
  EXPECT_EQ(render::bloom_levels(1.0, 1), 1);
  EXPECT_EQ(render::bloom_levels(1.0, 24), 3);
}

TEST_F(Bloom, OffByDefaultItAddsNoPassAndChangesNoPixel) {
  WorldOptions plain{.scene = "atrium", .lights = 24u, .mode = "deferred", .size = kSize};
  World world(plain);
  world.frame(0.0);
  EXPECT_FALSE(has_pass(world, "bloom composite"));
  const assets::Image without = world.renderer().read_output();
  World zero(bloom_options(0.0, "deferred"));
  zero.frame(0.0);
  EXPECT_EQ(assets::max_channel_difference(without, zero.renderer().read_output()), 0);
}

// Replaces the lit image after lighting with one drawn by `fill` (clears of
// the colour target), so that what the bloom makes of it is its filter, seen directly.
template <typename Fill>
void replace_lit_image(World& world, Fill fill) {
  world.registry().resource<render::FrameModules>().add({render::FrameStage::AfterLighting, "test image", [fill](render::FrameBuild& build) {
    const render::ResourceId color = build.frame.scene_color;
    build.graph.add_pass("test image", [&](render::PassBuilder& pass) { pass.write(color, render::Access::Transfer); },
                         [color, fill](const render::PassResources& res) { fill(res.texture(color)); });
  }, {}});
}

// A black frame with one bright 2x2 spot, centred where the chain's levels
// have texel corners (160x90: x 80, y 40), so the glow can be round.
TEST_F(Bloom, ABrightSpotSpreadsARoundGlowThatFallsOffWithDistanceAndAddsNoLight) {
  constexpr float kStrength = 0.5f, kValue = 1000.0f;
  constexpr int cx = 80, cy = 40;
  World world(bloom_options(kStrength));
  replace_lit_image(world, [](GLuint texture) {
    const float black[] = {0.0f, 0.0f, 0.0f, 1.0f}, bright[] = {kValue, kValue, kValue, 1.0f};
    glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, black);
    glClearTexSubImage(texture, 0, cx - 1, cy - 1, 0, 2, 2, 1, GL_RGBA, GL_FLOAT, bright);
  });
  const auto captured = testing::capture_textures(world, {"bloom-color", "bloom-down-1"}, render::FrameStage::Output);
  world.frame(0.0);
  ASSERT_TRUE(captured->count("bloom-color"));
  const std::vector<glm::vec4>& image = captured->at("bloom-color");
  ASSERT_EQ(image.size(), static_cast<std::size_t>(kSize.x) * kSize.y);
  EXPECT_EQ(captured->at("bloom-down-1").size(), static_cast<std::size_t>(kSize.x / 2) * (kSize.y / 2)) << "the first level is half the size";
  auto at = [&](int x, int y) { return image[static_cast<std::size_t>(y) * kSize.x + x].g; };
  double total = 0.0;
  for (const glm::vec4& texel : image) total += texel.g;
  // Karis's average on the first level damps a lone spot this bright (that
  // is what stops such spots flickering), so some of its glow is lost; none is made.
  EXPECT_LE(total, 1.01 * 4.0 * kValue) << "bloom adds no light";
  EXPECT_GE(total, (1.0 - kStrength) * 4.0 * kValue) << "the spot keeps the share the strength leaves it";
  EXPECT_GT(at(cx, cy), (1.0f - kStrength) * kValue) << "the spot keeps most of its light";
  float previous = at(cx, cy);
  for (const int d : {3, 6, 12, 24}) {
    const float right = at(cx + d, cy), left = at(cx - 1 - d, cy), up = at(cx, cy + d), down = at(cx, cy - 1 - d);
    EXPECT_GT(right, 0.0f) << "glow at " << d << " px";
    EXPECT_LT(right, previous) << "falls off at " << d << " px";
    EXPECT_NEAR(left, right, 0.1f * right) << "symmetric at " << d << " px";
    EXPECT_NEAR(up, right, 0.1f * right) << "round at " << d << " px";
    EXPECT_NEAR(down, up, 0.1f * up) << "symmetric at " << d << " px";
    previous = right;
  }
  // Glow a tenth of the width away is still some 14 levels of 255 once
  // tone-mapped (0.02 at exposure 1): it reaches as far as its radius says.
  EXPECT_GT(at(cx + kSize.x / 10, cy), 0.02f);
}

// Uniform light stays as it was: every level and the glow are normalised.
TEST_F(Bloom, UniformLightIsLeftAsItWas) {
  World world(bloom_options(1.0));
  replace_lit_image(world, [](GLuint texture) {
    const float grey[] = {2.0f, 2.0f, 2.0f, 1.0f};
    glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, grey);
  });
  const auto captured = testing::capture_textures(world, {"bloom-color"}, render::FrameStage::Output);
  world.frame(0.0);
  ASSERT_TRUE(captured->count("bloom-color"));
  for (const glm::vec4& texel : captured->at("bloom-color")) ASSERT_NEAR(texel.g, 2.0f, 0.01f);
}

TEST_F(Bloom, ItBrightensTheSurroundingsOfLightsVisibly) {
  World off(bloom_options(0.0)), on(bloom_options(0.3));
  off.frame(0.0);
  on.frame(0.0);
  const assets::Image without = off.renderer().read_output(), with = on.renderer().read_output();
  assets::write_png("bloom_forward.png", with);
  EXPECT_LT(assets::psnr(without, with), 35.0) << "a strength of 0.3 shows";
  EXPECT_GT(assets::psnr(without, with), 15.0) << "and keeps the picture";
}

// Every mode against forward with bloom on, from two views (the full
// five-view comparison of each mode runs with bloom off elsewhere).
void expect_every_mode_matches_forward(WorldOptions options, const std::string& name) {
  World world(options);
  testing::compare_every_mode_with_forward(world, [&](const std::string& mode, int view, const assets::Image& reference,
                                                      const assets::Image& image) {
    EXPECT_TRUE(has_pass(world, "bloom composite")) << name << ": " << mode;
    EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << name << ": " << mode << " view " << view;
    if (view == 1 && mode == "clustered-deferred") assets::write_png("bloom_" + name + ".png", image);
  }, {1, 4});
}

TEST_F(Bloom, EveryModeDrawsTheForwardPictureWithBloomOn) { expect_every_mode_matches_forward(bloom_options(0.3), "modes"); }

TEST_F(Bloom, EveryModeDrawsTheForwardPictureWithBloomAndMsaa) {
  WorldOptions options = bloom_options(0.3);
  options.technique_options.msaa = 4;
  expect_every_mode_matches_forward(options, "msaa");
}

TEST_F(Bloom, EveryModeDrawsTheForwardPictureWithBloomOnTheComputeFreeTier) {
  WorldOptions options = bloom_options(0.3);
  options.technique_options.compute_free = true;
  expect_every_mode_matches_forward(options, "compute_free");
}

// With the compute stage the bloom's passes are compute passes too (each
// level stored with imageStore).
TEST_F(Bloom, EveryModeDrawsTheForwardPictureWithBloomInTheComputeStage) {
  WorldOptions options = bloom_options(0.3);
  options.lighting_stage = LightingStage::Compute;
  expect_every_mode_matches_forward(options, "compute_stage");
  World world(options);
  world.frame(0.0);
  std::size_t compute_programs = 0;
  world.registry().resource<render::GpuAssets>().shaders().for_each(
      [&](const std::vector<std::string>& files, const std::vector<gfx::ShaderDefine>&, const gfx::ShaderProgram&) {
        compute_programs += files.size() == 1 && files[0].starts_with("post/bloom/") && files[0].ends_with(".comp");
      });
  EXPECT_EQ(compute_programs, 4u) << "first and later downsample, upsample, composite";
}

TEST_F(Bloom, ItsChainIsADebugViewWithAndWithoutMsaa) {
  for (const int msaa : {1, 4}) {
    WorldOptions options = bloom_options(0.3, "deferred");
    options.technique_options.msaa = msaa;
    World world(options);
    world.frame(0.0);
    for (const char* view : {"bloom-down-2", "bloom-up-1", "bloom-color"}) {
      EXPECT_TRUE(world.renderer().offers(view)) << view;
      world.registry().resource<RendererSettings>().debug_view = view;
      world.frame(0.0);
      const assets::Image image = world.renderer().read_output();
      assets::write_png("bloom_view_" + std::string(view) + "_msaa" + std::to_string(msaa) + ".png", image);
      long lit = 0;
      for (std::size_t i = 0; i < image.rgba.size(); i += 4) lit += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2] > 30 ? 1 : 0;
      EXPECT_GT(lit, static_cast<long>(image.rgba.size() / 4 / 4)) << view << " msaa " << msaa << ": the view fills the output";
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << view;
    }
  }
}

TEST(BloomOptions, ComeFromTheCommandLineAndSceneFilesAndAreRefusedOutOfRange) {
  const std::string_view args[] = {"render", "--bloom", "0.25", "--bloom-radius", "0.5", "--out", "x.png"};
  const CliOptions options = parse_cli(args);
  EXPECT_EQ(options.system_options.at("bloom"), 0.25);
  EXPECT_EQ(options.system_options.at("bloom-radius"), 0.5);
  for (const char* bad : {"2", "-0.1", "nan", "x"}) {
    const std::string_view refused[] = {"render", "--bloom", bad, "--out", "x.png"};
    try {
      (void)parse_cli(refused);
      ADD_FAILURE() << bad;
    } catch (const UsageError& e) {
      EXPECT_STREQ(e.what(), ("--bloom expects a number from 0 to 1, got '" + std::string(bad) + "'").c_str());
    }
  }
  SystemOptions declared;
  declared.declare("bloom-radius", "bloom radius", 0.02, 1.0, SystemOption::Step::Fraction, render::kDefaultBloomRadius);
  EXPECT_EQ(declared.value("bloom-radius"), render::kDefaultBloomRadius) << "a radius never set starts at the default";
}

// Every file under src/ and shaders/ that mentions bloom: its own folders,
// and in the rest of the engine only its registration (and include) in
// app/world.cpp and its two option rows in app/command_line.cpp.
TEST(BloomCode, LivesInItsOwnFilesPlusOneRegistrationAndItsOptionRows) {
  EXPECT_EQ(testing::mentions_outside("bloom", {"src/render/post/bloom/", "shaders/post/bloom/"}),
            (std::map<std::string, int>{{"src/app/command_line.cpp", 4}, {"src/app/world.cpp", 2}}));
}

}  // namespace
}  // namespace atrium
