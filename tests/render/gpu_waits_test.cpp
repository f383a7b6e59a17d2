// A steady frame never waits for the GPU: after warm-up, every mode makes no
// call that could wait (gfx/gpu_waits.hpp counts them) with shadows, with
// MSAA, and under every debug view (the heatmap's and the fragment view's
// averages come back a frame late), all with occlusion culling on the GPU
// (--culling gpu; the CPU path reads its depth tiles back by nature, and is
// chosen only on software renderers, where that costs nothing).
// And light lists fill without a read-back: a jump from 10 lights to many in
// one frame is met in that frame (the lists are sized by entries per light),
// and a jump the count cannot foresee (every light's radius grown sixteenfold)
// still draws what forward draws (the lights that did not fit are shaded
// wherever they reach), shows the overflow a frame later, and the grown lists
// fit the frames after.
#include <deque>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "gfx/frame_pacer.hpp"
#include "gfx/limits.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "render/debug/debug_views.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

using GpuWaits = testing::GlTest;
constexpr glm::ivec2 kSize{64, 36};

WorldOptions steady_options(const std::string& mode) {
  WorldOptions options;
  options.lights = 64u;
  options.mode = mode;
  options.size = kSize;
  options.culling_device = CullingDevice::Gpu;
  return options;
}

// Frames until the lists have grown and the timer queries cycle, then one more.
std::uint32_t waits_after_warm_up(World& world) {
  for (int f = 0; f < 4; ++f) world.frame(1.0 / 60.0);
  world.frame(1.0 / 60.0);
  return world.renderer().stats().gpu_waits;
}

TEST_F(GpuWaits, NoSteadyFrameWaitsInAnyMode) {
  for (const std::string& mode : techniques::mode_names()) {
    World world(steady_options(mode));
    EXPECT_EQ(waits_after_warm_up(world), 0u) << mode;
    world.registry().resource<RendererSettings>().shadows = 4;
    EXPECT_EQ(waits_after_warm_up(world), 0u) << mode << " with 4 shadowed lights";
  }
}

TEST_F(GpuWaits, NoSteadyFrameWaitsWithMsaa) {
  for (const std::string& mode : techniques::mode_names({.msaa = 4})) {
    WorldOptions options = steady_options(mode);
    options.technique_options.msaa = 4;
    World world(options);
    EXPECT_EQ(waits_after_warm_up(world), 0u) << mode << " with 4x MSAA";
  }
}

TEST_F(GpuWaits, NoSteadyFrameWaitsUnderAnyDebugView) {
  for (const std::string& mode : {std::string("forward"), std::string("tiled-deferred"), std::string("clustered-deferred"),
                                  std::string("light-prepass")}) {
    WorldOptions options = steady_options(mode);
    options.shadows = 2;
    World world(options);
    world.frame(1.0 / 60.0);
    // A view the mode does not offer draws its plain frame, whose waits the
    // test above counts; every view it offers is shown, its resources' too.
    std::vector<std::string> offered;
    for (const render::OfferedView& view : world.renderer().offered_views()) offered.push_back(view.name);
    EXPECT_GT(offered.size(), 4u) << mode;
    for (const std::string& view : offered) {
      world.registry().resource<RendererSettings>().debug_view = view;
      EXPECT_EQ(waits_after_warm_up(world), 0u) << mode << ", debug view " << view;
    }
  }
}

// Frames submitted back to back keep the GPU at most FramePacer::kFramesInFlight
// frames behind, and the CPU waits for it only before a frame, uncounted: once
// frame N is recorded, a fence placed after frame N - 3 has passed, and no
// frame counts a wait. The passes are timed by queries here, as on a GPU,
// not by a glFinish after each. llvmpipe keeps up even so; zink over lavapipe
// falls behind, and without the pacer each of these frames counted one to five
// waits inside it (ctest zink.gpu_waits runs this test there).
TEST_F(GpuWaits, AFrameLoopStaysTwoFramesAheadOfTheGpuAndWaitsOnlyBetweenFrames) {
  static_assert(gfx::FramePacer::kFramesInFlight == 2);
  WorldOptions options = steady_options("clustered-deferred");
  options.lights = 1024u;
  options.size = {320, 180};
  World world(options);
  world.renderer().timer() = gfx::PassTimer(gfx::TimingMethod::GpuQueries);
  for (int f = 0; f < 4; ++f) world.frame(1.0 / 60.0);
  std::deque<gfx::Fence> after_frame;  // placed after each of the last frames, oldest first
  for (int f = 0; f < 12; ++f) {
    world.frame(1.0 / 60.0);
    EXPECT_EQ(world.renderer().stats().gpu_waits, 0u) << "frame " << f;
    if (after_frame.size() == gfx::FramePacer::kFramesInFlight + 1) {
      EXPECT_FALSE(after_frame.front().wait_uncounted()) << "frame " << f << ": the GPU was more than two frames behind";
      after_frame.pop_front();
    }
    after_frame.emplace_back().place();
  }
}

TEST_F(GpuWaits, AJumpToManyLightsIsMetInTheFrameItHappensWithoutWaiting) {
  // llvmpipe ends a shader's loops after 65,535 iterations; past that many
  // lights it sizes the lists in the frame (a counted wait), so the jump stays under it there.
  const std::uint32_t many = gfx::shader_loop_limit() ? 60'000u : 100'000u;
  for (const std::string mode : {"tiled-deferred", "clustered-deferred", "clustered-forward"}) {
    WorldOptions options = steady_options("forward");
    options.size = {48, 27};  // forward loops over every light for every pixel
    options.lights = many;
    options.light_radius = 0.5f;
    World reference_world(options);
    reference_world.frame(0.0);
    const assets::Image reference = reference_world.renderer().read_output();

    options.lights = 10u;
    options.mode = mode;
    World world(options);
    for (int f = 0; f < 3; ++f) world.frame(0.0);
    world.set_light_count(many);
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().gpu_waits, 0u) << mode << ": the jump frame reads nothing back";
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode << ": the jump frame drops no light";
    world.frame(0.0);
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().light_list_overflows, 0u) << mode << ": the lists were sized for the new count in the jump frame";
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode;
  }
}

TEST_F(GpuWaits, ListsThatOverflowDrawEveryLightWithoutWaitingAndGrow) {
  for (const std::string mode : {"tiled-deferred", "clustered-deferred", "clustered-forward"}) {
    WorldOptions options = steady_options("forward");
    options.size = testing::kSize;
    options.lights = 2048u;
    options.light_radius = 4.0f;
    World reference_world(options);
    reference_world.frame(0.0);
    const assets::Image reference = reference_world.renderer().read_output();

    options.light_radius = 0.25f;
    options.mode = mode;
    World world(options);
    for (int f = 0; f < 3; ++f) world.frame(0.0);
    const std::uint32_t overflows = world.renderer().stats().light_list_overflows;
    world.set_light_radius(4.0f);  // each light now reaches many more bins: the lists cannot know
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().gpu_waits, 0u) << mode << ": the frame that overflows reads nothing back";
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode << ": no light is lost";
    world.frame(0.0);
    const std::uint32_t after_jump = world.renderer().stats().light_list_overflows;
    EXPECT_GT(after_jump, overflows) << mode << ": the overflow arrives a frame later";
    world.frame(0.0);
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().light_list_overflows, after_jump) << mode << ": the grown lists fit";
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode;
  }
}

}  // namespace
}  // namespace atrium
