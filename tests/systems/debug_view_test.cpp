// Debug views: each renders something, each differs from the others, and the
// heatmap's counts are the light evaluations each mode really performs.
#include <cmath>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "support/gl_test.hpp"
#include "systems/lighting/debug_views.hpp"

namespace atrium {
namespace {

constexpr glm::ivec2 kSize{160, 90};

using DebugViewRender = testing::GlTest;

TEST_F(DebugViewRender, EveryViewRendersNonBlankAndDistinct) {
  World world({"atrium", 48u, "deferred", 1, kSize});
  std::vector<assets::Image> images;
  for (const auto name : lighting::kDebugViews) {
    world.registry().resource<RendererSettings>().debug_view = std::string(name);
    world.frame(0.0);
    images.push_back(world.renderer().read_output());
    assets::write_png("debug_view_" + std::string(name) + ".png", images.back());
    int lit = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) lit += assets::luma(images.back(), x, y) > 0.02;
    }
    // Emission covers only the lamps; everything else fills most of the view.
    EXPECT_GT(lit, name == "emissive" ? 10 : kSize.x * kSize.y / 3) << name;
  }
  for (std::size_t a = 0; a < images.size(); ++a) {
    for (std::size_t b = a + 1; b < images.size(); ++b) {
      EXPECT_LT(assets::psnr(images[a], images[b]), 30.0) << lighting::kDebugViews[a] << " vs " << lighting::kDebugViews[b];
    }
  }
  world.registry().resource<RendererSettings>().debug_view.clear();
  world.frame(0.0);
}

double coverage(World& world) {
  const std::vector<float> depth = world.renderer().read_depth();
  double covered = 0;
  for (float d : depth) covered += d < 1.0f;
  return covered / static_cast<double>(depth.size());
}

double evaluations(World& world, const char* mode) {
  world.set_mode(mode);
  world.frame(0.0);
  return world.renderer().stats().light_evaluations_per_pixel;
}

TEST_F(DebugViewRender, HeatmapCountsWhatEachModeEvaluates) {
  constexpr std::uint32_t kLights = 40;
  World world({"atrium", kLights, "deferred", 1, kSize});
  world.registry().resource<RendererSettings>().debug_view = "heatmap";
  const double deferred = evaluations(world, "deferred");
  // Deferred evaluates every light once for every covered pixel, exactly.
  world.registry().resource<RendererSettings>().debug_view.clear();
  world.frame(0.0);
  const double covered = coverage(world);
  world.registry().resource<RendererSettings>().debug_view = "heatmap";
  EXPECT_NEAR(deferred, kLights * covered, 1e-9);
  const double radius = evaluations(world, "deferred-radius");
  const double volumes = evaluations(world, "light-volumes");
  const double instanced = evaluations(world, "light-volumes-instanced");
  const double forward = evaluations(world, "forward");
  EXPECT_LT(radius, deferred * 0.9) << "radius culling skips lights";
  // The stencil finds the pixels inside each volume's mesh, which circumscribes
  // the sphere: the same pixels as the radius test, plus a thin shell.
  EXPECT_GE(volumes, radius);
  EXPECT_LE(volumes, radius * 1.1);
  EXPECT_GE(instanced, volumes) << "without the stencil, pixels in front of a sphere are shaded too";
  EXPECT_GE(forward, deferred) << "forward shades overdrawn fragments too";
}

}  // namespace
}  // namespace atrium
