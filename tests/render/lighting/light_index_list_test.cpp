// Light lists (LightIndexList) from lights of every size: a few lights each
// under thousands of tiles or clusters are gathered bin by bin
// (common/light_gather.glsl), many small ones scattered (each walks its own
// bins), and either way the tiled and clustered pictures equal forward's; the
// two assignments write the same lists, and a gather that overflows loses no light.
#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "render/lighting/light_index_list.hpp"
#include "render/techniques/clustered/clustered.hpp"
#include "render/techniques/tiled/tiled.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using LightIndexListTest = testing::GlTest;

// 320x180 has 240 tiles: a light of 12 m covers more than a work group's 64.
constexpr glm::ivec2 kWide{320, 180};

// The lists of the world's technique, read back (tiled or clustered).
std::vector<std::vector<std::uint32_t>> lists_of(World& world) {
  const auto* technique = world.renderer().technique();
  if (const auto* tiled = dynamic_cast<const techniques::TiledTechnique*>(technique)) return tiled->list().read();
  return dynamic_cast<const techniques::ClusteredTechnique*>(technique)->grid().read_lists();
}

void set_assignment(World& world, LightAssignment assignment) {
  world.registry().resource<RendererSettings>().technique_options.light_assignment = assignment;
}

// With `assignment` (Automatic: the rule's choice, `expected`).
void expect_lists_match_forward(WorldOptions options, LightAssignment assignment, LightAssignment expected) {
  options.mode = "forward";
  World reference_world(options);
  reference_world.frame(0.0);
  const assets::Image reference = reference_world.renderer().read_output();
  for (const std::string mode : {"tiled-deferred", "clustered-forward", "clustered-deferred"}) {
    options.mode = mode;
    World world(options);
    set_assignment(world, assignment);
    world.frame(0.0);
    world.frame(0.0);
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode << ", " << *options.lights << " lights";
    EXPECT_EQ(world.renderer().stats().light_list_overflows, 0u) << mode;
    EXPECT_EQ(world.renderer().stats().light_assignment, expected) << mode;
  }
}

TEST_F(LightIndexListTest, AFewLargeLightsAreGatheredAndMatchForward) {
  expect_lists_match_forward({.scene = "atrium", .lights = 24u, .size = kWide, .light_radius = 12.0f}, LightAssignment::Automatic,
                             LightAssignment::Gather);
}

TEST_F(LightIndexListTest, ManySmallLightsScatteredMatchForward) {
  expect_lists_match_forward({.scene = "atrium", .lights = 3000u, .size = kWide, .light_radius = 0.6f}, LightAssignment::Scatter,
                             LightAssignment::Scatter);
}

// Same bins, same test: the gather writes the scatter's lists, light order
// included, so the pictures are the same to the bit (pixel boxes and grid
// boxes, tiles and clusters).
TEST_F(LightIndexListTest, GatherAndScatterWriteTheSameListsAndPictures) {
  for (const std::string mode : {"tiled-deferred", "clustered-deferred", "clustered-forward"}) {
    std::vector<std::vector<std::vector<std::uint32_t>>> lists;
    std::vector<assets::Image> images;
    for (const auto assignment : {LightAssignment::Scatter, LightAssignment::Gather}) {
      World world({.scene = "atrium", .lights = 300u, .mode = mode, .view = 2, .size = {160, 90}, .light_radius = 2.5f});
      set_assignment(world, assignment);
      if (mode == "clustered-forward") world.registry().resource<RendererSettings>().technique_options.cluster_bounds = ClusterBounds::Grid;
      world.frame(0.0);
      world.frame(0.0);
      EXPECT_EQ(world.renderer().stats().light_assignment, assignment) << mode;
      lists.push_back(lists_of(world));
      images.push_back(world.renderer().read_output());
    }
    ASSERT_EQ(lists[0].size(), lists[1].size()) << mode;
    std::size_t entries = 0;
    for (std::size_t b = 0; b < lists[0].size(); ++b) {
      EXPECT_EQ(lists[0][b], lists[1][b]) << mode << ", bin " << b;
      entries += lists[0][b].size();
    }
    EXPECT_GT(entries, 300u) << mode << ": lights reach several bins";
    EXPECT_EQ(images[0].rgba, images[1].rgba) << mode;
  }
}

// A gathered frame whose lists do not fit (the lights grew past what the
// lists were sized for) shades every light wherever it reaches, waits for
// nothing, and the lists grow for the frames after.
TEST_F(LightIndexListTest, AGatherThatOverflowsLosesNoLightAndGrows) {
  for (const std::string mode : {"tiled-deferred", "clustered-deferred"}) {
    WorldOptions options{.scene = "atrium", .lights = 2048u, .mode = "forward", .size = {160, 90}, .light_radius = 4.0f};
    options.culling_device = CullingDevice::Gpu;  // occlusion culling on the CPU reads depth back: a wait of its own
    World reference_world(options);
    reference_world.frame(0.0);
    const assets::Image reference = reference_world.renderer().read_output();
    options.mode = mode;
    options.light_radius = 0.25f;
    World world(options);
    set_assignment(world, LightAssignment::Gather);
    for (int f = 0; f < 3; ++f) world.frame(0.0);
    world.set_light_radius(4.0f);
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().gpu_waits, 0u) << mode;
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode << ": no light is lost";
    world.frame(0.0);
    const std::uint32_t after_jump = world.renderer().stats().light_list_overflows;
    EXPECT_EQ(after_jump, 1u) << mode << ": the overflow arrives a frame later";
    world.frame(0.0);
    world.frame(0.0);
    EXPECT_EQ(world.renderer().stats().light_list_overflows, after_jump) << mode << ": the grown lists fit";
    EXPECT_GE(assets::psnr(reference, world.renderer().read_output()), kMinimumPsnr) << mode;
  }
}

// Automatic gathers where enough of the bin-light pairs are hits, never
// before a total has arrived, and never past a driver's loop cap.
TEST(LightIndexListRule, DenseLightsAreGatheredAndSparseOnesScattered) {
  using lighting::LightIndexList;
  constexpr std::uint32_t kLights = 1024, kBins = 600;
  auto entries_at = [](double density) { return static_cast<std::uint64_t>(density * kBins * kLights); };
  struct Rule {
    bool software, sliced;
    double threshold;
  };
  for (const Rule rule : {Rule{true, false, lighting::kGatherDensitySoftware}, Rule{true, true, lighting::kGatherDensitySoftware},
                          Rule{false, false, lighting::kGatherDensityGpuTiles}, Rule{false, true, lighting::kGatherDensityGpuClusters}}) {
    SCOPED_TRACE(std::string(rule.software ? "software" : "GPU") + (rule.sliced ? ", clusters" : ", tiles"));
    auto choice = [&](std::uint32_t lights, std::uint64_t entries, std::uint32_t bins) {
      return LightIndexList::assignment_for(lights, entries, bins, 0, rule.software, rule.sliced);
    };
    EXPECT_EQ(choice(kLights, entries_at(0.2), kBins), LightAssignment::Gather);
    EXPECT_EQ(choice(kLights, entries_at(rule.threshold * 1.01), kBins), LightAssignment::Gather);
    EXPECT_EQ(choice(kLights, entries_at(rule.threshold / 2), kBins), LightAssignment::Scatter);
    EXPECT_EQ(choice(kLights, 0, 0), LightAssignment::Scatter) << "nothing arrived yet";
    EXPECT_EQ(choice(0, 0, 0), LightAssignment::Scatter);
  }
  EXPECT_LT(lighting::kGatherDensityGpuClusters, lighting::kGatherDensityGpuTiles) << "empty clusters cost the scatter, not the gather";
  constexpr std::uint32_t kMany = lighting::kGatherMostLightsGpu + 1;
  EXPECT_EQ(LightIndexList::assignment_for(kMany, std::uint64_t{kMany} * 100, 1000, 0, false, true), LightAssignment::Scatter)
      << "a GPU scatters past kGatherMostLightsGpu lights, however dense";
  EXPECT_EQ(LightIndexList::assignment_for(kMany, std::uint64_t{kMany} * 100, 1000, 0, true, true), LightAssignment::Gather)
      << "a software renderer without a loop cap still gathers";
  EXPECT_EQ(LightIndexList::assignment_for(kLights, entries_at(0.2), kBins, 65535, true, false), LightAssignment::Gather);
  EXPECT_EQ(LightIndexList::assignment_for(100000, std::uint64_t{20000} * 1000, 1000, 65535, true, false), LightAssignment::Scatter)
      << "a walk over 100,000 lights passes llvmpipe's loop cap";
}

// Few lights on a GPU spread their bins over work groups sooner, so that they
// fill it; a software renderer, whose barriers cost more, keeps one rule.
TEST(LightIndexListRule, LargeLightsAreFewerCandidatesWhenTheLightsAreFewOnAGpu) {
  using lighting::LightIndexList;
  EXPECT_EQ(LightIndexList::big_light_candidates(24, false), 32u);
  EXPECT_EQ(LightIndexList::big_light_candidates(1024, false), 32u);
  EXPECT_EQ(LightIndexList::big_light_candidates(4096, false), 128u);
  EXPECT_EQ(LightIndexList::big_light_candidates(16384, false), 512u);
  EXPECT_EQ(LightIndexList::big_light_candidates(1u << 20, false), 512u);
  for (const std::uint32_t lights : {24u, 1024u, 1u << 20}) EXPECT_EQ(LightIndexList::big_light_candidates(lights, true), 512u);
}

}  // namespace
}  // namespace atrium
