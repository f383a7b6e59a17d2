// Frustum culling: the plane tests against boxes, spheres and normal cones
// with known answers, and in the running engine that culling changes no pixel
// of any view or mode, drops what the camera cannot see, follows entities that
// move, and keeps draw calls from growing with copies of the scene; meshlets
// facing away are dropped only where the transform keeps their normal cones
// true (not mirrored, not stretched).
#include "app/cli.hpp"
#include "systems/frustum_culling.hpp"

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "components/visibility.hpp"
#include "gfx/depth.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"

namespace atrium {
namespace {

// A camera at the origin looking down -Z with a 90-degree field of view.
Frustum test_frustum() {
  return frustum_of(gfx::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f));
}

TEST(FrustumOf, KeepsBoxesInsideOrCrossingAndDropsBoxesOutside) {
  const Frustum frustum = test_frustum();
  EXPECT_TRUE(intersects(frustum, {-1, -1, -11}, {1, 1, -9})) << "straight ahead";
  EXPECT_TRUE(intersects(frustum, {-100, -100, -50}, {100, 100, -40})) << "larger than the view";
  EXPECT_TRUE(intersects(frustum, {9, -1, -11}, {12, 1, -9})) << "crossing the right plane (x = -z)";
  EXPECT_TRUE(intersects(frustum, {-1, -1, -1}, {1, 1, 1})) << "around the camera";
  EXPECT_FALSE(intersects(frustum, {-1, -1, 5}, {1, 1, 7})) << "behind";
  EXPECT_FALSE(intersects(frustum, {12, -1, -11}, {14, 1, -9})) << "right of the view";
  EXPECT_FALSE(intersects(frustum, {-1, 12, -11}, {1, 14, -9})) << "above the view";
  EXPECT_FALSE(intersects(frustum, {-1, -1, -0.05f}, {1, 1, -0.01f})) << "before the near plane";
  EXPECT_FALSE(intersects(frustum, {-1, -1, -300}, {1, 1, -200})) << "beyond the far plane";
}

// What lies wholly inside needs no test of its parts; what crosses a plane does.
TEST(FrustumOf, ContainsOnlyBoxesWhollyInside) {
  const Frustum frustum = test_frustum();
  EXPECT_TRUE(contains(frustum, {-1, -1, -11}, {1, 1, -9})) << "straight ahead";
  EXPECT_FALSE(contains(frustum, {9, -1, -11}, {12, 1, -9})) << "crossing the right plane (x = -z)";
  EXPECT_FALSE(contains(frustum, {-1, -1, -1}, {1, 1, 1})) << "around the camera";
  EXPECT_FALSE(contains(frustum, {-1, -1, -101}, {1, 1, -99})) << "crossing the far plane";
  EXPECT_FALSE(contains(frustum, {-1, -1, 5}, {1, 1, 7})) << "behind";
}

TEST(FrustumOf, SpheresAreTestedAtTheirDistanceFromEachPlane) {
  const Frustum frustum = test_frustum();
  // The right plane is x = -z; (12, 0, -10) lies 2 / sqrt(2) = 1.41 outside it.
  EXPECT_FALSE(intersects(frustum, glm::vec3{12, 0, -10}, 1.4f));
  EXPECT_TRUE(intersects(frustum, glm::vec3{12, 0, -10}, 1.42f));
  EXPECT_FALSE(intersects(frustum, glm::vec3{0, 0, 0.5f}, 0.55f)) << "behind the near plane";
  EXPECT_TRUE(intersects(frustum, glm::vec3{0, 0, 0.5f}, 0.65f));
}

TEST(FrustumOf, ANonFiniteMatrixKeepsEveryBox) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Frustum frustum = frustum_of(glm::mat4(nan));
  EXPECT_TRUE(intersects(frustum, {-1, -1, 5}, {1, 1, 7}));
  EXPECT_TRUE(intersects(frustum, glm::vec3{0, 0, 5}, 1.0f));
  EXPECT_FALSE(contains(frustum, {-1, -1, 5}, {1, 1, 7})) << "contains nothing, so every part is tested";
}

// Triangles facing +Z whose normals spread up to 60 degrees from the cone's
// axis (meshoptimizer's cutoff is the sine of the spread): every one faces
// away only from an eye behind them, within the cutoff of the axis.
TEST(FacesAway, OnlyFromBehindTheConeAndNeverFromItsApex) {
  MeshletBounds meshlet;
  meshlet.cone_apex = {0, 0, 0};
  meshlet.cone_axis = {0, 0, 1};
  meshlet.cone_cutoff = std::sin(glm::radians(60.0f));
  EXPECT_TRUE(faces_away(meshlet, {0, 0, -5})) << "straight behind";
  EXPECT_TRUE(faces_away(meshlet, {1, 0, -5})) << "behind, within the cutoff";
  EXPECT_FALSE(faces_away(meshlet, {5, 0, -1})) << "beside";
  EXPECT_FALSE(faces_away(meshlet, {0, 0, 5})) << "in front";
  EXPECT_FALSE(faces_away(meshlet, {0, 0, 0})) << "on the apex";
  meshlet.cone_cutoff = 2.0f;
  EXPECT_FALSE(faces_away(meshlet, {0, 0, -5})) << "a cone that cannot tell";
}

using FrustumCulling = testing::GlTest;

using testing::kSize;

TEST_F(FrustumCulling, ChangesNoPixelOfAnyViewOrModeAndDropsWhatIsOutOfView) {
  WorldOptions culled_options{.scene = "atrium", .lights = 48u, .mode = "forward", .size = kSize};
  WorldOptions whole_options = culled_options;
  whole_options.frustum_culling = false;
  World culled(culled_options);
  World whole(whole_options);
  for (int view = 1; view <= 5; ++view) {
    culled.set_view(view);
    whole.set_view(view);
    for (const std::string mode : {"forward", "deferred", "clustered-deferred", "light-volumes"}) {
      culled.set_mode(mode);
      whole.set_mode(mode);
      culled.frame(0.0);
      whole.frame(0.0);
      EXPECT_LE(assets::max_channel_difference(culled.renderer().read_output(), whole.renderer().read_output()), 1)
          << mode << " view " << view;
    }
    const render::FrameStats& with = culled.renderer().stats();
    const render::FrameStats& without = whole.renderer().stats();
    EXPECT_EQ(without.triangles_drawn, without.triangles) << "view " << view;
    EXPECT_EQ(with.triangles, without.triangles);
    // Every stored view looks into the courtyard: some of it is behind or beside
    // the camera, and some faces away (whole meshlets of it).
    EXPECT_LT(with.triangles_drawn, with.triangles) << "view " << view;
    EXPECT_GT(with.triangles_drawn, with.triangles / 4) << "view " << view;
    EXPECT_LE(with.draw_calls, without.draw_calls);
  }
}

// Three spheres in front of the camera: as built, mirrored, and stretched.
std::unique_ptr<World> spheres(bool culling) {
  assets::AssetManager manager;
  assets::MeshAsset asset;
  asset.materials.emplace_back();
  asset.meshes.push_back({"sphere", {assets::add_geometry(asset, assets::shapes::sphere(1.0f, 64, 32), 0)}});
  assets::SceneDescription scene;
  const assets::MeshAssetHandle handle = manager.add_mesh_asset(std::move(asset));
  const glm::quat turn = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
  scene.instances.push_back({handle, 0, Transform{glm::vec3(-2.5f, 0.0f, 0.0f), turn, glm::vec3(1.0f)}});
  scene.instances.push_back({handle, 0, Transform{glm::vec3(0.0f, 0.0f, 0.0f), turn, glm::vec3(-1.0f, 1.0f, 1.0f)}});
  scene.instances.push_back({handle, 0, Transform{glm::vec3(2.5f, 0.0f, 0.0f), turn, glm::vec3(0.6f, 1.6f, 1.0f)}});
  scene.lights.push_back({glm::vec3(0.0f, 2.0f, 4.0f), glm::vec3(1.0f), 8.0f, 20.0f});
  scene.views.push_back({"front", glm::vec3(0.0f, 0.0f, 6.0f), 0.0f, 0.0f});
  WorldOptions options{.scene = "", .mode = "forward", .size = kSize};
  options.frustum_culling = culling;
  return std::make_unique<World>(std::move(manager), std::move(scene), options);
}

TEST_F(FrustumCulling, MeshletsFacingAwayAreDroppedWithoutChangingAPixelOfMirroredOrStretchedCopies) {
  const auto culled = spheres(true), whole = spheres(false);
  for (const std::string mode : {"forward", "clustered-forward", "deferred"}) {
    culled->set_mode(mode);
    whole->set_mode(mode);
    culled->frame(0.0);
    whole->frame(0.0);
    const assets::Image image = culled->renderer().read_output();
    assets::write_png("culling_spheres_" + mode + ".png", image);
    EXPECT_LE(assets::max_channel_difference(image, whole->renderer().read_output()), 1) << mode;
  }
  const CullingStats& stats = culled->registry().resource<CullingStats>();
  ASSERT_GT(stats.meshlets, 0u);
  // Only the first sphere's cones may cull, and some of its far side does.
  EXPECT_LT(stats.meshlets_visible, stats.meshlets);
  EXPECT_GE(stats.meshlets_visible, stats.meshlets - stats.meshlets / 3);
  std::size_t index = 0;
  culled->registry().view<MeshInstance, WorldBounds>().each([&](const MeshInstance&, const WorldBounds& bounds) {
    std::size_t cones = 0;
    for (const MeshletBounds& m : bounds.meshlets) cones += m.cone_cutoff <= 1.0f;
    if (index == 0) EXPECT_GE(cones, bounds.meshlets.size() / 2) << "a rotated copy keeps its cones";
    else EXPECT_EQ(cones, 0u) << "mirrored or stretched: no cone, copy " << index;
    ++index;
  });
  EXPECT_EQ(index, 3u);
}

TEST_F(FrustumCulling, ACameraLookingAwayFromTheSceneDrawsNothingButTheBackground) {
  WorldOptions options{.scene = "atrium", .lights = 16u, .mode = "clustered-deferred", .size = kSize};
  options.camera = assets::NamedView{"away", glm::vec3(0.0f, 5.0f, 60.0f), 180.0f, 0.0f};  // yaw 180 looks along +Z
  World world(options);
  world.frame(0.0);
  const render::FrameStats& stats = world.renderer().stats();
  EXPECT_EQ(stats.triangles_drawn, 0u);
  EXPECT_EQ(stats.draw_calls, 0u);
  EXPECT_EQ(stats.objects_drawn, 0u);
  EXPECT_GT(stats.objects, 100u);
  const assets::Image image = world.renderer().read_output();
  for (int y = 0; y < kSize.y; y += 7) {
    for (int x = 0; x < kSize.x; x += 7) ASSERT_EQ(image.pixel(x, y)[0], image.pixel(0, 0)[0]) << x << "," << y;
  }
}

TEST_F(FrustumCulling, AnEntityMovedOutOfViewLeavesTheDrawAndItsBoxFollowsIt) {
  World world({.scene = "atrium", .lights = 8u, .mode = "forward", .view = 4, .size = kSize});  // the overview sees every entity
  world.frame(0.0);
  auto& registry = world.registry();
  ecs::Entity moved{};
  registry.view<Transform, MeshInstance, Visibility>().each([&](ecs::Entity e, const Transform&, const MeshInstance&, const Visibility& v) {
    if (v.any && moved.is_null()) moved = e;
  });
  ASSERT_FALSE(moved.is_null());
  const std::size_t drawn_before = world.renderer().stats().objects_drawn;
  const glm::vec3 box_before = registry.get<WorldBounds>(moved).min;
  registry.get<Transform>(moved).position.y += 1000.0f;
  world.frame(0.0);
  EXPECT_NEAR(registry.get<WorldBounds>(moved).min.y, box_before.y + 1000.0f, 1e-2f);
  EXPECT_FALSE(registry.get<Visibility>(moved).any);
  EXPECT_EQ(world.renderer().stats().objects_drawn, drawn_before - 1);
  registry.get<Transform>(moved).position.y -= 1000.0f;
  world.frame(0.0);
  EXPECT_TRUE(registry.get<Visibility>(moved).any);
  EXPECT_EQ(world.renderer().stats().objects_drawn, drawn_before);
}

// scenes/courtyard-grid.json: twelve copies of the courtyard.
const std::string kGrid = std::string(ATRIUM_SOURCE_DIR) + "/scenes/courtyard-grid.json";

TEST_F(FrustumCulling, TheGridSceneIsBistroScaleAndDrawsWithTheDrawCallsOfOneCourtyard) {
  World single({.scene = "atrium", .lights = 0u, .mode = "deferred", .view = 4, .size = kSize});
  single.frame(0.0);
  World grid({.scene = kGrid, .mode = "deferred", .size = kSize});
  grid.frame(0.0);
  const render::FrameStats& stats = grid.renderer().stats();
  EXPECT_GE(stats.triangles, 2'500'000u);
  EXPECT_GE(stats.objects, 1500u);
  EXPECT_EQ(stats.lights, 4096u);
  EXPECT_EQ(stats.objects_drawn, stats.objects) << "the overview sees every copy";
  EXPECT_EQ(stats.draw_calls, single.renderer().stats().draw_calls) << "copies share materials: no more draws";
  // A view down into one courtyard submits a small part of the scene.
  grid.set_view(3);
  grid.frame(0.0);
  EXPECT_LT(grid.renderer().stats().triangles_drawn, stats.triangles / 10);
  EXPECT_LE(grid.renderer().stats().draw_calls, single.renderer().stats().draw_calls);
}

TEST_F(FrustumCulling, TheGridSceneDrawsTheForwardPictureInClusteredModes) {
  World grid({.scene = kGrid, .mode = "forward", .view = 3, .size = kSize});
  grid.frame(0.0);
  const assets::Image reference = grid.renderer().read_output();
  assets::write_png("grid_view_3_forward.png", reference);
  for (const std::string mode : {"clustered-deferred", "clustered-forward", "tiled-deferred"}) {
    grid.set_mode(mode);
    grid.frame(0.0);
    EXPECT_GE(assets::psnr(reference, grid.renderer().read_output()), kMinimumPsnr) << mode;
  }
}

}  // namespace
}  // namespace atrium
