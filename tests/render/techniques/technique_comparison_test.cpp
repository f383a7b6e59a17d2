// Every lighting technique draws the picture forward draws: each mode in the
// technique table, with each G-buffer layout, against forward on the built-in
// scene at 160x90 from all five views, PSNR at least 40 dB. New techniques are
// covered by their row.
#include <cmath>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/gl_object.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

using testing::kSize;

class TechniqueMatchesForward : public testing::GlTest,
                                public ::testing::WithParamInterface<std::tuple<std::string, GBufferLayout>> {};

TEST_P(TechniqueMatchesForward, FromEveryView) {
  const auto& [mode, layout] = GetParam();
  World world({.scene = "atrium", .mode = "forward", .size = kSize, .technique_options = testing::with_layout(layout)});
  testing::expect_forward_picture_from_every_view(world, mode, testing::test_name(mode, layout));
}

INSTANTIATE_TEST_SUITE_P(Modes, TechniqueMatchesForward, ::testing::ValuesIn(testing::mode_layouts()),
                         [](const auto& info) { return testing::test_name(std::get<0>(info.param), std::get<1>(info.param)); });

// The Phong models factor into the same terms as Cook-Torrance (brdf.glsl's
// brdf_terms and brdf_combine), which the light pre-pass sums apart: every mode
// draws forward's picture with them too.
class TechniqueMatchesForwardShaded : public testing::GlTest,
                                      public ::testing::WithParamInterface<std::tuple<std::string, std::string>> {};

TEST_P(TechniqueMatchesForwardShaded, FromEveryView) {
  const auto& [mode, model] = GetParam();
  World world({.scene = "atrium", .mode = "forward", .size = kSize, .shading = model});
  testing::expect_forward_picture_from_every_view(world, mode, mode + "_" + model);
}

INSTANTIATE_TEST_SUITE_P(Modes, TechniqueMatchesForwardShaded,
                         ::testing::Combine(::testing::ValuesIn(testing::non_forward_modes()), ::testing::Values("blinn-phong", "phong")),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + "_" + std::get<1>(info.param);
                           for (char& c : name) if (c == '-') c = '_';
                           return name;
                         });

using ShadingModels = testing::GlTest;

TEST_F(ShadingModels, GiveDifferentPicturesAndSwitchAtRunTime) {
  World world({.scene = "atrium", .mode = "deferred", .view = 3, .size = kSize});
  std::vector<assets::Image> images;
  for (const char* model : {"pbr", "blinn-phong", "phong", "pbr"}) {
    world.registry().resource<RendererSettings>().shading = model;
    world.frame(0.0);
    images.push_back(world.renderer().read_output());
  }
  // The models are normalised to light a scene equally bright, so they differ
  // mostly in highlights: clearly, but not by much on average.
  for (auto [a, b] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
    EXPECT_LT(assets::psnr(images[static_cast<std::size_t>(a)], images[static_cast<std::size_t>(b)]), 45.0) << a << " " << b;
    EXPECT_GE(assets::max_channel_difference(images[static_cast<std::size_t>(a)], images[static_cast<std::size_t>(b)]), 16) << a << " " << b;
  }
  EXPECT_TRUE(std::isinf(assets::psnr(images[0], images[3]))) << "switching back gives the same picture";
}

using ModeSwitching = testing::GlTest;

TEST_F(ModeSwitching, AHundredSwitchesLeaveTheLiveGlObjectsUnchanged) {
  World world({.scene = "atrium", .lights = 32u, .mode = "forward", .size = {64, 36}});
  const auto modes = techniques::technique_table();
  // One full round first: every technique's programs are compiled and cached.
  for (const auto& info : modes) {
    world.set_mode(std::string(info.name));
    world.frame(0.0);
  }
  world.set_mode("forward");
  world.frame(0.0);
  const std::int64_t before = gfx::live_gl_objects();
  for (int i = 0; i < 100; ++i) {
    world.set_mode(std::string(modes[static_cast<std::size_t>(i) % modes.size()].name));
    world.frame(0.0);
  }
  world.set_mode("forward");
  world.frame(0.0);
  EXPECT_EQ(gfx::live_gl_objects(), before);
}

}  // namespace
}  // namespace atrium
