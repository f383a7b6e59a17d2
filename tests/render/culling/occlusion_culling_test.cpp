// Occlusion culling: the depth pyramid's box test on its own, then the
// Bistro-scale grid (scenes/courtyard-grid.json), whose street views hide most
// of what is in view: every mode draws the picture it draws without occlusion
// culling while submitting a fraction of the triangles, also in the first frame
// after the camera jumps (when what the last frame showed says little), and
// from the second frame after it no more than it shows.
#include "render/culling/occlusion_culling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/depth.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/shader_library.hpp"
#include "render/binding_slots.hpp"
#include "render/frame/frame_uniforms.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"

namespace atrium {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A camera at the origin looking down -Z, 90 degrees wide, on a 64x64 viewport
// (8x8 tiles), every tile at `depth` unless `hole` names one at infinity.
struct Scene {
  glm::mat4 view{1.0f};
  glm::mat4 projection = gfx::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
  render::DepthPyramid pyramid(float depth, glm::ivec2 hole = glm::ivec2(-1)) const {
    std::vector<float> tiles(64, depth);
    if (hole.x >= 0) tiles[static_cast<std::size_t>(hole.y) * 8 + hole.x] = kInfinity;
    return render::DepthPyramid(std::move(tiles), glm::ivec2(8), glm::ivec2(64));
  }
  bool hides(const render::DepthPyramid& p, glm::vec3 centre, float half) const {
    return p.hides(view, projection, 0.1f, centre - half, centre + half);
  }
};

TEST(DepthPyramid, HidesABoxBehindTheDepthAndNothingThatReachesInFrontOfIt) {
  const Scene scene;
  const render::DepthPyramid wall = scene.pyramid(10.0f);
  EXPECT_TRUE(scene.hides(wall, glm::vec3(0.0f, 0.0f, -20.0f), 1.0f));
  EXPECT_TRUE(scene.hides(wall, glm::vec3(3.0f, -2.0f, -11.5f), 1.0f)) << "nearest corner at 10.5 m";
  EXPECT_FALSE(scene.hides(wall, glm::vec3(0.0f, 0.0f, -10.5f), 1.0f)) << "nearest corner at 9.5 m, in front";
  EXPECT_FALSE(scene.hides(wall, glm::vec3(0.0f, 0.0f, -5.0f), 1.0f));
  EXPECT_FALSE(scene.hides(wall, glm::vec3(0.0f, 0.0f, -10.0f), 0.0f)) << "a point on the wall is not behind it";
}

TEST(DepthPyramid, OneUncoveredTileUnderTheBoxKeepsItAtEveryLevel) {
  const Scene scene;
  for (int x = 0; x < 8; ++x) {
    const render::DepthPyramid holed = scene.pyramid(10.0f, glm::ivec2(x, 3));
    // A box over the whole screen: read at the pyramid's coarsest levels.
    EXPECT_FALSE(scene.hides(holed, glm::vec3(0.0f, 0.0f, -50.0f), 40.0f)) << "hole in tile " << x;
  }
  // A small box over tile (6, 3) only (pixels 48-55, 24-31): the hole at (1, 3) does not matter.
  const render::DepthPyramid holed = scene.pyramid(10.0f, glm::ivec2(1, 3));
  const float ndc_x = (52.0f / 64.0f) * 2.0f - 1.0f, ndc_y = (28.0f / 64.0f) * 2.0f - 1.0f;
  EXPECT_TRUE(scene.hides(holed, glm::vec3(ndc_x * 20.0f, ndc_y * 20.0f, -20.0f), 0.2f));
  EXPECT_FALSE(scene.hides(scene.pyramid(10.0f, glm::ivec2(6, 3)), glm::vec3(ndc_x * 20.0f, ndc_y * 20.0f, -20.0f), 0.2f));
}

TEST(DepthPyramid, KeepsBoxesAtTheNearPlaneBehindTheCameraOrOffScreen) {
  const Scene scene;
  const render::DepthPyramid wall = scene.pyramid(1.0f);
  EXPECT_FALSE(scene.hides(wall, glm::vec3(0.0f, 0.0f, -0.1f), 0.05f)) << "crosses the near plane";
  EXPECT_FALSE(scene.hides(wall, glm::vec3(0.0f, 0.0f, 20.0f), 1.0f)) << "behind the camera";
  EXPECT_FALSE(scene.hides(wall, glm::vec3(200.0f, 0.0f, -20.0f), 1.0f)) << "off screen to the right";
  EXPECT_FALSE(scene.hides(render::DepthPyramid(), glm::vec3(0.0f, 0.0f, -20.0f), 1.0f)) << "no depth read";
}

// Each picture test runs with the test on the CPU (the depth read back) and on
// the GPU (render/culling/gpu_occlusion_culling.hpp: nothing read back).
class OcclusionCulling : public testing::GlTest, public ::testing::WithParamInterface<CullingDevice> {};

using testing::kSize;
const std::string kGrid = std::string(ATRIUM_SOURCE_DIR) + "/scenes/courtyard-grid.json";

void set_occlusion_culling(World& world, bool on, CullingDevice device = CullingDevice::Cpu) {
  auto& settings = world.registry().resource<RendererSettings>();
  settings.occlusion_culling = on;
  settings.culling_device = device;
}

struct Frame {
  assets::Image image;
  std::size_t triangles_drawn = 0;
  std::size_t triangles_occluded = 0;
};

// One frame; its counts as they stand once the GPU has finished it (on the
// GPU path they arrive a frame or more late).
Frame draw(World& world) {
  world.frame(0.0);
  world.renderer().settle();
  return {world.renderer().read_output(), world.renderer().stats().triangles_drawn, world.renderer().stats().triangles_occluded};
}

// The frames a still camera takes to draw no more than it shows when
// occlusion culling starts in a view whose cut has passed (it was drawn
// without culling): the first tests against the depth of what the culling
// last showed, elsewhere, and keeps what that does not hide; the second draws
// all of it first, and its depth, the full one, tells the third what to draw
// (one pyramid a frame; on a cut the first frame reads the full depth too).
void learn(World& world) {
  draw(world);
  draw(world);
}

TEST_P(OcclusionCulling, TheGridStreetsDrawTheSamePictureFromAFractionOfTheTriangles) {
  World world({.scene = kGrid, .lights = 256u, .mode = "clustered-deferred", .size = kSize});
  for (int view = 1; view <= 5; ++view) {
    world.set_view(view);
    set_occlusion_culling(world, false);
    const Frame all = draw(world);
    set_occlusion_culling(world, true, GetParam());
    learn(world);
    const Frame culled = draw(world);
    assets::write_png("occlusion_grid_view" + std::to_string(view) + ".png", culled.image);
    EXPECT_EQ(all.triangles_occluded, 0u);
    EXPECT_EQ(culled.triangles_drawn + culled.triangles_occluded, all.triangles_drawn) << "view " << view;
    EXPECT_GE(assets::psnr(all.image, culled.image), 60.0) << "view " << view;
    // The street views (court, avenue, gallery) see the other courtyards
    // through the first one's walls.
    if (view == 2 || view == 4 || view == 5) {
      EXPECT_LT(culled.triangles_drawn, all.triangles_drawn / 3) << "view " << view;
    }
  }
}

TEST_P(OcclusionCulling, AfterTheCameraJumpsTheFirstFrameDrawsWhatTheLastHidAndTheNextNoMoreThanItShows) {
  World world({.scene = kGrid, .lights = 256u, .mode = "clustered-forward", .view = 4, .size = kSize});
  World reference({.scene = kGrid, .lights = 256u, .mode = "clustered-forward", .view = 4, .size = kSize});
  set_occlusion_culling(world, true, GetParam());
  set_occlusion_culling(reference, false);
  draw(world);
  draw(world);
  // From the avenue to each other view: the last frame hid or never saw most
  // of what shows now.
  for (const int view : {2, 1, 5, 3}) {
    world.set_view(view);
    reference.set_view(view);
    const Frame jumped = draw(world);
    const Frame all = draw(reference);
    EXPECT_GE(assets::psnr(all.image, jumped.image), 60.0) << "view " << view;
    EXPECT_EQ(jumped.triangles_drawn + jumped.triangles_occluded, all.triangles_drawn)
        << "view " << view << ": every triangle in view is drawn or counted as hidden, the frame of the jump too";
    // The jump was a cut (set_view): its frame chose from the full depth what
    // the next draws, so that one is already as lean as the frames after it.
    const Frame next = draw(world);
    const Frame steady = draw(world);
    EXPECT_GE(assets::psnr(all.image, next.image), 60.0) << "view " << view;
    EXPECT_EQ(next.triangles_drawn, steady.triangles_drawn) << "view " << view;
  }
}

TEST_P(OcclusionCulling, EveryModeDrawsItsPictureWithoutWhatTheDepthHides) {
  for (const int samples : {1, 4}) {
    WorldOptions options{.scene = kGrid, .lights = 256u, .mode = "forward", .view = 5, .size = kSize};
    options.technique_options.msaa = samples;
    World world(options);
    for (const std::string& mode : techniques::mode_names(options.technique_options)) {
      world.set_mode(mode);
      set_occlusion_culling(world, false);
      const Frame all = draw(world);
      set_occlusion_culling(world, true, GetParam());
      learn(world);
      const Frame culled = draw(world);
      EXPECT_GE(assets::psnr(all.image, culled.image), 60.0) << mode << ", MSAA " << samples;
      EXPECT_LT(culled.triangles_drawn, all.triangles_drawn / 3) << mode << ", MSAA " << samples;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Device, OcclusionCulling, ::testing::Values(CullingDevice::Cpu, CullingDevice::Gpu),
                         [](const ::testing::TestParamInfo<CullingDevice>& info) {
                           return info.param == CullingDevice::Cpu ? std::string("Cpu") : std::string("Gpu");
                         });

// The pyramid's finest level (culling/depth_tiles.comp), against a loop over
// the pixels: each 8x8 tile holds the farthest view depth of its pixels,
// infinity where one shows the background, tiles cut by the viewport's edge
// only the pixels inside it (70x45: 9x6 tiles, the last column 6 pixels wide,
// the last row 5 high; two work groups of 8 tiles across, the second mostly
// past the edge).
using DepthTiles = testing::GlTest;

TEST_F(DepthTiles, HoldTheFarthestViewDepthOfTheirPixelsUpToTheViewportsEdge) {
  constexpr glm::ivec2 kViewport{70, 45};
  constexpr float kNear = 0.1f, kFar = 100.0f;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> depth_of(0.001f, 1.0f);
  std::vector<float> depth(static_cast<std::size_t>(kViewport.x * kViewport.y));
  for (float& d : depth) d = depth_of(random);
  depth[static_cast<std::size_t>(20 * kViewport.x + 33)] = gfx::kDepthFar;  // background in tile (4, 2)
  gfx::Texture texture = gfx::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, GL_DEPTH_COMPONENT32F, kViewport.x, kViewport.y);
  glTextureSubImage2D(texture.id(), 0, 0, 0, kViewport.x, kViewport.y, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());

  render::FrameUniforms frame{};
  frame.viewport_size = glm::vec2(kViewport);
  frame.near_plane = kNear;
  frame.far_plane = kFar;
  gfx::Buffer uniforms = gfx::create_buffer();
  glNamedBufferStorage(uniforms.id(), sizeof frame, &frame, 0);
  glBindBufferBase(GL_UNIFORM_BUFFER, render::kFrameUniformBinding, uniforms.id());
  const glm::ivec2 tiles = (kViewport + 7) / 8;
  const auto count = static_cast<std::size_t>(tiles.x * tiles.y);
  gfx::Buffer out = gfx::create_buffer();
  glNamedBufferStorage(out.id(), static_cast<GLsizeiptr>(count * sizeof(float)), nullptr, 0);
  gfx::ShaderLibrary shaders;
  render::write_depth_tiles(shaders, texture.id(), tiles, out.id());
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> farthest(count);
  gfx::read_buffer(out.id(), 0, static_cast<GLsizeiptr>(count * sizeof(float)), farthest.data());
  glUseProgram(0);

  for (int ty = 0; ty < tiles.y; ++ty) {
    for (int tx = 0; tx < tiles.x; ++tx) {
      float smallest = gfx::kDepthNear;
      for (int y = ty * 8; y < std::min(ty * 8 + 8, kViewport.y); ++y) {
        for (int x = tx * 8; x < std::min(tx * 8 + 8, kViewport.x); ++x) smallest = std::min(smallest, depth[static_cast<std::size_t>(y * kViewport.x + x)]);
      }
      const float expected = smallest <= gfx::kDepthFar ? kInfinity : kNear * kFar / (kNear + smallest * (kFar - kNear));
      const float got = farthest[static_cast<std::size_t>(ty * tiles.x + tx)];
      if (std::isinf(expected)) {
        EXPECT_TRUE(std::isinf(got)) << "tile " << tx << "," << ty;
      } else {
        EXPECT_NEAR(got, expected, expected * 1e-5f) << "tile " << tx << "," << ty;
      }
    }
  }
  EXPECT_TRUE(std::isinf(farthest[static_cast<std::size_t>(2 * tiles.x + 4)])) << "the tile with a background pixel";
}

// The GPU's box test is the CPU's twin: from the same depth both leave out the
// same triangles, view after view, and the GPU's frame reads nothing back.
using OcclusionCullingTwins = testing::GlTest;

TEST_F(OcclusionCullingTwins, TheGpuHidesWhatTheCpuHidesWithoutWaiting) {
  World cpu({.scene = kGrid, .lights = 256u, .mode = "tiled-deferred", .size = kSize});
  World gpu({.scene = kGrid, .lights = 256u, .mode = "tiled-deferred", .size = kSize});
  set_occlusion_culling(cpu, true, CullingDevice::Cpu);
  set_occlusion_culling(gpu, true, CullingDevice::Gpu);
  for (int view = 1; view <= 5; ++view) {
    cpu.set_view(view);
    gpu.set_view(view);
    learn(cpu);
    learn(gpu);
    const Frame on_cpu = draw(cpu);
    gpu.frame(0.0);
    EXPECT_EQ(gpu.renderer().stats().gpu_waits, 0u) << "view " << view;
    EXPECT_TRUE(gpu.renderer().stats().culled_on_gpu);
    EXPECT_FALSE(cpu.renderer().stats().culled_on_gpu);
    gpu.renderer().settle();
    const Frame on_gpu{gpu.renderer().read_output(), gpu.renderer().stats().triangles_drawn, gpu.renderer().stats().triangles_occluded};
    EXPECT_GT(on_gpu.triangles_occluded, 0u) << "view " << view;
    EXPECT_EQ(on_gpu.triangles_occluded, on_cpu.triangles_occluded) << "view " << view;
    EXPECT_EQ(on_gpu.triangles_drawn, on_cpu.triangles_drawn) << "view " << view;
    EXPECT_EQ(assets::psnr(on_cpu.image, on_gpu.image), std::numeric_limits<double>::infinity()) << "view " << view;
  }
}

}  // namespace
}  // namespace atrium
