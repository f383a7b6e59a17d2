// MSAA (--msaa, src/render/lighting/sample_rate.hpp): every mode with MSAA
// draws forward-with-MSAA's picture; MSAA brings every mode's picture closer to
// a 16x supersampled one (edges smoothed, not just changed); the edges view
// marks silhouettes and nothing without MSAA; a Blender export's silhouettes
// match forward pixel for pixel; the visibility buffer shades each surface of
// an edge pixel once; a sample count the driver cannot hold is refused naming
// the limit.
#include <cmath>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/limits.hpp"
#include "support/box_downsample.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

using testing::kSize;
constexpr int kSamples = 4;  // llvmpipe's most

TechniqueOptions with_msaa(int samples, GBufferLayout layout = GBufferLayout::Full) {
  TechniqueOptions options = testing::with_layout(layout);
  options.msaa = samples;
  return options;
}

class MsaaMatchesForward : public testing::GlTest,
                           public ::testing::WithParamInterface<std::tuple<std::string, GBufferLayout>> {};

TEST_P(MsaaMatchesForward, FromEveryView) {
  const auto& [mode, layout] = GetParam();
  World world({.scene = "atrium", .mode = "forward", .size = kSize, .technique_options = with_msaa(kSamples, layout)});
  // A few edge pixels may differ more: per-sample depth decides which surface
  // a sample shows, and the passes differ in how they test it.
  testing::expect_forward_picture_from_every_view(world, mode, "msaa_" + testing::test_name(mode, layout), 0.002);
}

INSTANTIATE_TEST_SUITE_P(Modes, MsaaMatchesForward, ::testing::ValuesIn(testing::mode_layouts({.msaa = kSamples})),
                         [](const auto& info) { return testing::test_name(std::get<0>(info.param), std::get<1>(info.param)); });

using Msaa = testing::GlTest;

// A model Blender wrote (a teapot of 9,176 triangles with vertex colours),
// small on screen against the sky: most of its pixels are edges. On such
// silhouettes a pixel is shaded once at its centre, off the triangle, and its
// position there is not among the depths the depth buffer holds for its
// samples: the tiled and clustered modes must bin lights from the positions
// they shade (clustered lost every light on 17 such pixels of one view), and
// light-volumes must not light an edge's empty samples (it lit 220 twice).
TEST_F(Msaa, SilhouettesOfABlenderExportMatchForwardPixelForPixel) {
  const std::string model = std::string(ATRIUM_SOURCE_DIR) + "/tests/data/gltf-tools/blender-colors.glb";
  for (const auto layout : testing::gbuffer_layouts()) {
    World world({.scene = model, .lights = 16, .mode = "forward", .size = {320, 180}, .technique_options = with_msaa(kSamples, layout)});
    testing::compare_every_mode_with_forward(world, [&](const std::string& mode, int view, const assets::Image& reference,
                                                        const assets::Image& image) {
      const std::string name = testing::test_name(mode, layout) + " view " + std::to_string(view);
      // Measured 59.6 dB at worst, and at most two pixels off by more than 24
      // levels: a grazing silhouette's centre is extrapolated far off its
      // triangle, and the G-buffer's 8-bit roughness and 16-bit normals move
      // the sharp highlight forward finds there.
      EXPECT_GE(assets::psnr(reference, image), 50.0) << name;
      EXPECT_LE(testing::share_differing(reference, image, 24) * 320 * 180, 2.0) << name;
    });
  }
}

// Per-sample shading on edges is what smooths them in the deferred modes: were
// edge pixels shaded once, their samples would all get one surface's colour.
TEST_F(Msaa, BringsEveryModeCloserToASupersampledPicture) {
  for (const int view : {1, 3}) {
    World big({.scene = "atrium", .mode = "forward", .view = view, .size = kSize * 4});
    big.frame(0.0);
    const assets::Image supersampled = testing::box_downsample(big.renderer().read_output(), 4, true);
    // One World each way, switching modes (a World compiles its programs anew).
    World plain({.scene = "atrium", .mode = "forward", .view = view, .size = kSize});
    World smoothed({.scene = "atrium", .mode = "forward", .view = view, .size = kSize, .technique_options = with_msaa(kSamples)});
    for (const std::string& mode : techniques::mode_names(with_msaa(kSamples))) {
      plain.set_mode(mode);
      plain.frame(0.0);
      smoothed.set_mode(mode);
      smoothed.frame(0.0);
      const double without = assets::psnr(supersampled, plain.renderer().read_output());
      const double with = assets::psnr(supersampled, smoothed.renderer().read_output());
      EXPECT_GE(with, without + 3.0) << mode << " view " << view << ": " << without << " dB without MSAA, " << with << " with";
    }
  }
}

std::size_t red_pixels(const assets::Image& image) {
  std::size_t red = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) red += image.rgba[i] > 200 && image.rgba[i + 1] < 80;
  return red;
}

TEST_F(Msaa, EdgesViewMarksSilhouettesAndNothingWithoutMsaa) {
  for (const char* mode : {"deferred", "light-prepass", "forward"}) {
    World world({.scene = "atrium", .mode = mode, .size = kSize, .debug_view = "msaa-edges", .technique_options = with_msaa(kSamples)});
    world.frame(0.0);
    const assets::Image edges = world.renderer().read_output();
    assets::write_png(std::string("msaa_edges_") + mode + ".png", edges);
    const double share = static_cast<double>(red_pixels(edges)) / (kSize.x * kSize.y);
    // The court's columns, arches and lamps have edges; its floor and sky do not.
    EXPECT_GT(share, 0.02) << mode;
    EXPECT_LT(share, 0.4) << mode;
  }
  World plain({.scene = "atrium", .mode = "deferred", .size = kSize, .debug_view = "msaa-edges"});
  plain.frame(0.0);
  EXPECT_EQ(red_pixels(plain.renderer().read_output()), 0u);
}

// The visibility buffer's own view of what it shades more than once: the
// pixels whose samples show two surfaces or more, which are the silhouettes,
// creases and seams the deferred modes' edge view marks (not the floor's
// grid of triangles); offered with MSAA only.
TEST_F(Msaa, SurfacesViewMarksThePixelsTheVisibilityBufferShadesMoreThanOnce) {
  World world({.scene = "atrium", .mode = "visibility-buffer", .size = kSize, .debug_view = "msaa-surfaces",
               .technique_options = with_msaa(kSamples)});
  world.frame(0.0);
  const assets::Image shared = world.renderer().read_output();
  assets::write_png("msaa_surfaces_visibility_buffer.png", shared);
  const double share = static_cast<double>(red_pixels(shared)) / (kSize.x * kSize.y);
  World deferred({.scene = "atrium", .mode = "clustered-deferred", .size = kSize, .debug_view = "msaa-edges",
                  .technique_options = with_msaa(kSamples)});
  deferred.frame(0.0);
  const double edges = static_cast<double>(red_pixels(deferred.renderer().read_output())) / (kSize.x * kSize.y);
  EXPECT_GT(share, 0.02);
  EXPECT_LT(share, 1.2 * edges);
  World plain({.scene = "atrium", .mode = "visibility-buffer", .size = kSize});
  plain.frame(0.0);
  for (const render::OfferedView& view : plain.renderer().offered_views()) EXPECT_NE(view.name, "msaa-surfaces");
}

// The visibility buffer stores an identifier a sample and shades each surface
// a pixel shows once: samples of two triangles share a shading where their
// rebuilt surfaces pass the deferred modes' edge test. Shading each triangle
// once, as forward+'s fragment shader runs, evaluated 46 lights a pixel here,
// since the built-in scene's floor and walls are cut into a fine grid; by
// surface it evaluates 25, against clustered-deferred's 29.5 (its edges also
// catch the G-buffer's rounding) and 15.9 without MSAA.
TEST_F(Msaa, VisibilityBufferShadesEachSurfaceOfAPixelOnce) {
  const auto evaluations = [](const std::string& mode, int samples) {
    World world({.scene = "atrium", .mode = mode, .size = kSize, .debug_view = "heatmap", .technique_options = with_msaa(samples)});
    world.frame(0.0);
    return world.renderer().stats().light_evaluations_per_pixel;
  };
  const double visibility = evaluations("visibility-buffer", kSamples);
  EXPECT_LE(visibility, 1.05 * evaluations("clustered-deferred", kSamples));
  EXPECT_LT(visibility, 0.7 * evaluations("clustered-forward", kSamples));
  EXPECT_GT(visibility, evaluations("visibility-buffer", 1));
}

TEST_F(Msaa, MoreSamplesThanTheDriverAllowsAreRefusedNamingTheLimit) {
  const int too_many = gfx::max_msaa_samples() * 2;
  try {
    World world({.scene = "atrium", .mode = "deferred", .size = kSize, .technique_options = with_msaa(too_many)});
    world.frame(0.0);
    FAIL() << "no error";
  } catch (const gfx::ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("this context allows at most " + std::to_string(gfx::max_msaa_samples())),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace atrium
