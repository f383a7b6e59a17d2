// The cluster grid: the GPU's light lists equal a CPU computation of the same
// grid (as sets), every depth maps to a valid slice in GLSL and C++ alike and
// each --z-slicing scheme cuts where it says, a list's first frame sizes it
// without losing a light, and --active-clusters changes no pixel.
#include <algorithm>
#include <array>
#include <map>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/camera.hpp"
#include "components/frame_resources.hpp"
#include "components/transform.hpp"
#include "gfx/depth.hpp"
#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"
#include "render/light_buffer.hpp"
#include "render/techniques/clustered/clustered.hpp"

namespace atrium {
namespace {

using ClusterGridTest = testing::GlTest;

const lighting::ClusterGrid& grid_of(World& world) {
  const auto* technique = dynamic_cast<const techniques::ClusteredTechnique*>(world.renderer().technique());
  if (!technique) throw std::logic_error("not a clustered technique");
  return technique->grid();
}

// Reads the grid's lists back and expects each to equal the CPU's computation
// of the same grid (light order included); returns the lists.
std::vector<std::vector<std::uint32_t>> expect_lists_equal_cpu(World& world) {
  const lighting::ClusterGrid& grid = grid_of(world);
  const auto gpu = grid.read_lists();
  const auto cpu = grid.assign_on_cpu(world.registry().resource<render::LightBuffer>().staging,
                                      world.registry().resource<ViewState>().view);
  EXPECT_EQ(gpu.size(), cpu.size());
  for (std::size_t c = 0; c < std::min(gpu.size(), cpu.size()); ++c) EXPECT_EQ(gpu[c], cpu[c]) << "cluster " << c;
  return gpu;
}

// Draws until the lists are sized: the first frame's total comes back after
// it (LightIndexList), so the second frame's lists hold every light.
void draw_settled(World& world) {
  world.frame(0.0);
  world.renderer().settle();
  world.frame(0.0);
}

constexpr std::array kSlicings{ZSlicing::Log, ZSlicing::Uniform, ZSlicing::PlainLog};

std::string name_of(ZSlicing slicing) { return std::string(kZSlicingNames[static_cast<std::size_t>(slicing)]); }

TEST_F(ClusterGridTest, GpuListsEqualACpuComputationOfTheSameGrid) {
  for (const ZSlicing slicing : kSlicings) {
    SCOPED_TRACE(name_of(slicing));
    World world({.scene = "atrium", .lights = 300u, .mode = "clustered-deferred", .view = 3, .size = {160, 90}});
    auto& options = world.registry().resource<RendererSettings>().technique_options;
    options.cluster_grid = ClusterGridSize::fixed({4, 3, 6});
    options.cluster_bounds = ClusterBounds::Grid;
    options.z_slicing = slicing;
    draw_settled(world);
    const lighting::ClusterGrid& grid = grid_of(world);
    ASSERT_EQ(grid.dims(), glm::uvec3(4, 3, 6));
    ASSERT_EQ(grid.slicing(), slicing);
    std::size_t assignments = 0;
    for (const auto& list : expect_lists_equal_cpu(world)) assignments += list.size();
    EXPECT_GT(assignments, 300u) << "lights overlap several clusters";
    EXPECT_EQ(grid.list().last_total(), assignments);
  }
}

// Near 0.1 m, far 100 m, eight slices: where each scheme puts the boundaries,
// checked through slice_of and through the clusters' boxes (view depth -z).
TEST_F(ClusterGridTest, EachSlicingSchemeCutsDepthWhereItSays) {
  constexpr float kNear = 0.1f, kFar = 100.0f;
  constexpr std::uint32_t kSlices = 8;
  const glm::mat4 projection = gfx::perspective(glm::radians(60.0f), 16.0f / 9.0f, kNear, kFar);
  // Where boundary b (0 = near, kSlices = far) lies under each scheme.
  auto boundary = [&](ZSlicing slicing, std::uint32_t b) -> float {
    const float t = static_cast<float>(b) / kSlices;
    switch (slicing) {
      case ZSlicing::Log:  // the first slice to ten near-plane distances, then equal ratios
        return b == 0 ? kNear : 1.0f * std::pow(kFar / 1.0f, static_cast<float>(b - 1) / (kSlices - 1));
      case ZSlicing::PlainLog: return kNear * std::pow(kFar / kNear, t);
      case ZSlicing::Uniform: return kNear + (kFar - kNear) * t;
    }
    return 0.0f;
  };
  EXPECT_NEAR(boundary(ZSlicing::PlainLog, 1), 0.23714f, 1e-4f);
  EXPECT_NEAR(boundary(ZSlicing::Uniform, 1), 12.5875f, 1e-4f);
  for (const ZSlicing slicing : kSlicings) {
    SCOPED_TRACE(name_of(slicing));
    lighting::ClusterGrid grid({2, 2, kSlices}, slicing);
    grid.update(projection, kNear, kFar);
    for (std::uint32_t z = 0; z < kSlices; ++z) {
      const float start = boundary(slicing, z), end = boundary(slicing, z + 1);
      EXPECT_EQ(grid.slice_of(start * 1.001f), z) << "just past the start of slice " << z;
      EXPECT_EQ(grid.slice_of(end * 0.999f), z) << "just before the end of slice " << z;
      const lighting::ClusterBox& box = grid.boxes()[z * 4];
      EXPECT_NEAR(-box.hi.z, start, start * 1e-4f) << "slice " << z;
      EXPECT_NEAR(-box.lo.z, end, end * 1e-4f) << "slice " << z;
    }
  }
}

TEST_F(ClusterGridTest, ManyLightsEqualTheCpuInLightOrder) {
  // Lights in hundreds of work groups write themselves into the lists in
  // whatever order their atomics run; the lists must still equal the CPU's,
  // light order included (the sort), long and short lists alike.
  constexpr std::uint32_t kLights = 40000;
  World world({.scene = "atrium", .lights = kLights, .mode = "clustered-forward", .size = {96, 54}, .light_radius = 0.4f});
  world.registry().resource<RendererSettings>().technique_options.cluster_grid = ClusterGridSize::fixed({4, 3, 6});
  world.registry().resource<RendererSettings>().technique_options.cluster_bounds = ClusterBounds::Grid;
  draw_settled(world);
  std::size_t longest = 0, late_lights = 0;
  for (const auto& list : expect_lists_equal_cpu(world)) {
    EXPECT_TRUE(std::is_sorted(list.begin(), list.end())) << "a cluster lists its lights in order";
    longest = std::max(longest, list.size());
    late_lights += static_cast<std::size_t>(std::count_if(list.begin(), list.end(), [](std::uint32_t l) { return l >= kLights - 5000; }));
  }
  EXPECT_GT(longest, 48u) << "some lists are long enough for the group sort";
  EXPECT_GT(late_lights, 100u) << "the last lights reach clusters too";
}

// The scan that turns the bins' counts into ranges runs in blocks of 4,096
// bins: a grid of 72 blocks (finer than 16-pixel clusters at 1080p, 261,120)
// still equals the CPU's lists, and the scatter's lists too long for one
// invocation to sort (the scan sizes their sort's dispatch) are sorted.
TEST_F(ClusterGridTest, AGridOfMoreThanAQuarterMillionClustersEqualsTheCpu) {
  World world({.scene = "atrium", .lights = 2500u, .mode = "clustered-forward", .size = {96, 54}, .light_radius = 3.0f});
  auto& options = world.registry().resource<RendererSettings>().technique_options;
  options.cluster_grid = ClusterGridSize::fixed({128, 72, 32});
  options.cluster_bounds = ClusterBounds::Grid;
  options.light_assignment = LightAssignment::Scatter;
  draw_settled(world);
  ASSERT_GT(grid_of(world).dims().x * grid_of(world).dims().y * grid_of(world).dims().z, 64u * 4096u);
  std::size_t longest = 0, entries = 0;
  for (const auto& list : expect_lists_equal_cpu(world)) {
    longest = std::max(longest, list.size());
    entries += list.size();
  }
  EXPECT_GT(longest, 128u) << "some lists are long enough for the work-group sort (kShortList)";
  EXPECT_EQ(grid_of(world).list().last_total(), entries);
}

TEST_F(ClusterGridTest, BoundsAreRebuiltOnlyWhenTheProjectionChanges) {
  World world({.scene = "atrium", .lights = 16u, .mode = "clustered-forward", .size = {64, 36}});
  world.frame(0.0);
  for (int step = 0; step < 20; ++step) {
    // Walking through the court keeps the depth planes, and so the projection.
    world.registry().view<Transform, Camera>().each([](Transform& t, Camera&) { t.position.x += 0.05f; });
    world.frame(0.0);
  }
  EXPECT_EQ(grid_of(world).rebuilds(), 1u);
  world.set_size({80, 36});  // a new aspect ratio is a new projection
  world.frame(0.0);
  EXPECT_EQ(grid_of(world).rebuilds(), 2u);
  world.frame(0.0);
  EXPECT_EQ(grid_of(world).rebuilds(), 2u);
}

TEST_F(ClusterGridTest, EveryDepthMapsToAValidSliceInGlslAndCpp) {
  for (const ZSlicing slicing : kSlicings) {
    SCOPED_TRACE(name_of(slicing));
    World world({.scene = "atrium", .lights = 4u, .mode = "clustered-deferred", .size = {64, 36}});
    world.registry().resource<RendererSettings>().technique_options.z_slicing = slicing;
    world.frame(0.0);
    const lighting::ClusterGrid& grid = grid_of(world);
    const ViewState& view = world.registry().resource<ViewState>();
    // Depths from before the near plane to beyond the far plane, including the
    // view depth that window depth 1.0 stands for (the far plane itself).
    std::vector<float> depths{0.0f, view.near_plane * 0.5f, view.near_plane, view.far_plane, view.far_plane * 2.0f};
    for (int i = 0; i <= 400; ++i) depths.push_back(view.near_plane * std::pow(view.far_plane / view.near_plane, i / 400.0f));
    for (int i = 0; i <= 400; ++i) depths.push_back(view.near_plane + (view.far_plane - view.near_plane) * (i / 400.0f));

    const std::vector<std::uint32_t> slices = testing::evaluate_glsl<std::uint32_t>(
        "#include \"common/frame.glsl\"\n#include \"common/clusters.glsl\"\n", "float", "uint", "cluster_slice(value)", depths,
        [&] { grid.bind(); });
    int disagreements = 0;
    for (std::size_t i = 0; i < depths.size(); ++i) {
      EXPECT_LT(slices[i], grid.dims().z) << "depth " << depths[i];
      // Only a depth on a slice boundary may round either way.
      disagreements += slices[i] != grid.slice_of(depths[i]);
    }
    EXPECT_LE(disagreements, 3);
    EXPECT_EQ(grid.slice_of(0.0f), 0u);
    EXPECT_EQ(grid.slice_of(view.far_plane), grid.dims().z - 1);
    EXPECT_EQ(grid.slice_of(view.far_plane * 2.0f), grid.dims().z - 1);
  }
}

// Slicing moves lights between lists, never out of the picture: both clustered
// modes under each scheme, with grid and pixel bounds, draw forward's image.
TEST_F(ClusterGridTest, EverySlicingSchemeDrawsTheForwardPicture) {
  World world({.scene = "atrium", .lights = 400u, .mode = "forward", .view = 2, .size = {160, 90}});
  world.frame(0.0);
  const assets::Image reference = world.renderer().read_output();
  auto& options = world.registry().resource<RendererSettings>().technique_options;
  for (const char* mode : {"clustered-forward", "clustered-deferred"}) {
    world.set_mode(mode);
    for (const ZSlicing slicing : kSlicings) {
      for (const ClusterBounds bounds : {ClusterBounds::Grid, ClusterBounds::Pixels}) {
        options.z_slicing = slicing;
        options.cluster_bounds = bounds;
        world.frame(0.0);
        EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr)
            << mode << " " << name_of(slicing) << (bounds == ClusterBounds::Grid ? " grid" : " pixels");
      }
    }
  }
}

TEST_F(ClusterGridTest, AListsFirstFrameSizesItAndLosesNoLight) {
  // 1024 lights need far more entries than the first guess (four per light):
  // with no earlier total to go by, the first frame reads its own back (one
  // counted wait) and runs again; the frames after never wait.
  constexpr glm::ivec2 kSize{96, 54};
  // Occlusion culling still reads depth back (issue 30 item 3): off, to count the lists' waits alone.
  World world({.scene = "atrium", .lights = 1024u, .mode = "forward", .size = kSize, .occlusion_culling = false});
  world.frame(0.0);
  const assets::Image reference = world.renderer().read_output();
  world.set_mode("clustered-deferred");
  world.frame(0.0);
  EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << "no light was lost in the first frame";
  EXPECT_EQ(world.renderer().stats().gpu_waits, 1u) << "the first frame sized its lists itself";
  const lighting::ClusterGrid& grid = grid_of(world);
  EXPECT_GT(grid.list().last_total(), 1024u * lighting::kFirstEntriesPerLight);
  EXPECT_GE(grid.list().capacity(), grid.list().last_total());
  world.frame(0.0);
  world.frame(0.0);
  EXPECT_EQ(world.renderer().stats().gpu_waits, 0u);
  EXPECT_EQ(grid_of(world).list().overflow_frames(), 0u) << "nothing overflowed";
  EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr);
}

TEST_F(ClusterGridTest, ActiveClustersOnlyChangeNoPixel) {
  World world({.scene = "atrium", .lights = 200u, .mode = "clustered-deferred", .view = 2, .size = {96, 54}});
  world.registry().resource<RendererSettings>().technique_options.cluster_bounds = ClusterBounds::Grid;
  world.frame(0.0);
  const assets::Image all = world.renderer().read_output();
  const std::uint32_t total_all = grid_of(world).list().last_total();
  world.registry().resource<RendererSettings>().technique_options.active_clusters = true;
  world.frame(0.0);
  EXPECT_TRUE(std::isinf(assets::psnr(all, world.renderer().read_output())));
  EXPECT_LT(grid_of(world).list().last_total(), total_all) << "empty clusters received no lights";
}

// Pixel bounds: each cluster's list is the grid list less the lights that miss
// every pixel it holds, so the picture is unchanged and far fewer lights are
// evaluated per pixel.
TEST_F(ClusterGridTest, PixelBoundsKeepEveryLightThatReachesAPixelAndDropMostThatDoNot) {
  for (const int view : {1, 3, 5}) {
    World world({.scene = "atrium", .lights = 1024u, .mode = "clustered-deferred", .view = view, .size = {160, 90}});
    auto& options = world.registry().resource<RendererSettings>().technique_options;
    options.cluster_bounds = ClusterBounds::Grid;
    draw_settled(world);
    const assets::Image grid_image = world.renderer().read_output();
    const auto grid_lists = grid_of(world).read_lists();
    options.cluster_bounds = ClusterBounds::Pixels;
    draw_settled(world);
    EXPECT_GE(assets::psnr(grid_image, world.renderer().read_output()), 50.0) << "view " << view;
    const auto pixel_lists = grid_of(world).read_lists();
    ASSERT_EQ(pixel_lists.size(), grid_lists.size());
    std::size_t grid_total = 0, pixel_total = 0;
    for (std::size_t c = 0; c < grid_lists.size(); ++c) {
      EXPECT_TRUE(std::includes(grid_lists[c].begin(), grid_lists[c].end(), pixel_lists[c].begin(), pixel_lists[c].end()))
          << "cluster " << c << " view " << view;
      grid_total += grid_lists[c].size();
      pixel_total += pixel_lists[c].size();
    }
    EXPECT_LT(pixel_total * 2, grid_total) << "view " << view;
  }
}

// Evaluated lights per pixel against those whose radius covers the pixel
// (deferred-radius evaluates exactly those), from the heatmap counters.
double evaluated_per_pixel(World& world, const std::string& mode) {
  world.set_mode(mode);
  world.registry().resource<RendererSettings>().debug_view = "heatmap";
  world.frame(0.0);
  world.renderer().settle();
  world.registry().resource<RendererSettings>().debug_view.clear();
  return world.renderer().stats().light_evaluations_per_pixel;
}

TEST_F(ClusterGridTest, PixelBoundsEvaluateAtLeastSevenOfTenLightsThatReachOnTheBuiltinSceneAt1024Lights) {
  double evaluated = 0.0, reaching = 0.0;
  for (int view = 1; view <= 5; ++view) {
    World world({.scene = "atrium", .lights = 1024u, .mode = "clustered-deferred", .view = view, .size = {320, 180}});
    reaching += evaluated_per_pixel(world, "deferred-radius");
    evaluated += evaluated_per_pixel(world, "clustered-deferred");
  }
  EXPECT_GE(reaching / evaluated, 0.7) << "reaching " << reaching / 5 << ", evaluated " << evaluated / 5 << " per pixel";
}

}  // namespace
}  // namespace atrium
