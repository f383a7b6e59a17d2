// Shadows (--shadows K) as a user sees them: a wall between a light and the
// floor leaves the far side dark, pixel for pixel against an analytic
// evaluation (a ray from each floor point to the light, tested against the
// wall's box), for point, spot and directional lights, and by a glowing wall,
// though not from a light inside it (lamp glass); every mode draws the
// forward picture with shadows on; maps are drawn again only for what moved;
// and the CPU parts (tile allocator, light selection) hold their promises.
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <set>

#include <glm/gtc/constants.hpp>

#include "app/world.hpp"
#include "assets/mesh_builder.hpp"
#include "base/frustum.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "gfx/depth.hpp"
#include "render/light_buffer.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"
#include "support/light_buffer_read_back.hpp"
#include "support/reference_shading.hpp"
#include "render/shadows/atlas_allocator.hpp"
#include "render/shadows/shadow_selection.hpp"

namespace atrium {
namespace {

using Shadows = testing::GlTest;

using testing::kSize;
constexpr float kHalf = 10.0f;
constexpr float kAmbient = 0.03f, kExposure = 1.3f;
// The wall: 8 m wide, 3 m tall, 0.3 m thick, across the floor at z = 0.
const glm::vec3 kWallMin(-4.0f, 0.0f, -0.15f), kWallMax(4.0f, 3.0f, 0.15f);
const testing::ReferenceMaterial kFloor{glm::vec3(0.7f), 0.0f, 0.6f};

// Whether the segment from `from` to `to` passes through the box (slab test).
bool segment_hits_box(glm::vec3 from, glm::vec3 to, glm::vec3 min, glm::vec3 max) {
  float t0 = 0.0f, t1 = 1.0f;
  const glm::vec3 d = to - from;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-9f) {
      if (from[a] < min[a] || from[a] > max[a]) return false;
      continue;
    }
    float near = (min[a] - from[a]) / d[a], far = (max[a] - from[a]) / d[a];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

// `glowing_wall`: the wall's material is emissive, as a lamp's glass is.
std::unique_ptr<World> wall_world(const assets::SceneLight& light, const char* mode, int shadows, bool glowing_wall = false) {
  assets::AssetManager manager;
  assets::MeshAsset mesh;
  assets::Material floor;
  floor.base_color_factor = glm::vec4(kFloor.albedo, 1.0f);
  floor.metallic_factor = kFloor.metallic;
  floor.roughness_factor = kFloor.roughness;
  mesh.materials.push_back(floor);
  assets::Material wall = floor;
  wall.base_color_factor = glm::vec4(0.5f, 0.4f, 0.3f, 1.0f);
  if (glowing_wall) wall.emissive_factor = glm::vec3(0.8f, 0.7f, 0.4f);
  mesh.materials.push_back(wall);
  mesh.meshes.push_back({"floor", {assets::add_geometry(mesh, assets::shapes::grid(glm::vec3(-kHalf, 0, kHalf), glm::vec3(2 * kHalf, 0, 0),
                                                                                    glm::vec3(0, 0, -2 * kHalf), 8, 8, 1.0f), 0)}});
  mesh.meshes.push_back({"wall", {assets::add_geometry(mesh, assets::shapes::box(kWallMin, kWallMax, 1.0f), 1)}});
  const auto handle = manager.add_mesh_asset(std::move(mesh));
  assets::SceneDescription scene;
  scene.instances.push_back({handle, 0, Transform{}});
  scene.instances.push_back({handle, 1, Transform{}});
  scene.lights.push_back(light);
  // Above and beside the wall, looking down across it: both sides of the wall in view.
  scene.views.push_back({"above", glm::vec3(9.0f, 9.0f, 0.0f), -90.0f, -55.0f});
  scene.ambient = glm::vec3(kAmbient);
  scene.exposure = kExposure;
  WorldOptions options{.scene = "", .mode = mode, .size = kSize};
  options.shadows = shadows;
  return std::make_unique<World>(std::move(manager), std::move(scene), options);
}

// Where the ray through pixel (x, y_up) first meets the floor, or nothing when
// it misses the floor or the wall is in front.
std::optional<glm::vec3> floor_point(const ViewState& view, int x, int y_up) {
  const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f, (y_up + 0.5f) / kSize.y * 2.0f - 1.0f);
  const glm::mat4 inverse = glm::inverse(view.view_projection);
  const glm::vec4 near = inverse * glm::vec4(ndc, 1.0f, 1.0f), far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 origin = glm::vec3(near) / near.w, dir = glm::normalize(glm::vec3(far) / far.w - origin);
  if (dir.y >= -1e-4f) return std::nullopt;
  const glm::vec3 p = origin + dir * (-origin.y / dir.y);
  if (std::abs(p.x) > kHalf - 0.05f || std::abs(p.z) > kHalf - 0.05f) return std::nullopt;
  // Seen past the wall (with a margin for its silhouette's pixels).
  if (segment_hits_box(origin, p, kWallMin - glm::vec3(0.1f), kWallMax + glm::vec3(0.1f))) return std::nullopt;
  return p;
}

// What reaches floor point p from the light, and whether the wall blocks it.
struct Incoming {
  glm::vec3 radiance{0.0f};
  glm::vec3 to_light{0.0f, 1.0f, 0.0f};  // normalised
  bool blocked = false;
};

Incoming incoming(const assets::SceneLight& light, glm::vec3 p) {
  Incoming in;
  if (light.kind == assets::LightKind::Directional) {
    in.to_light = -glm::normalize(light.direction);
    in.radiance = light.color * light.intensity;
    in.blocked = segment_hits_box(p, p + in.to_light * 100.0f, kWallMin, kWallMax);
    return in;
  }
  const glm::vec3 d = light.position - p;
  const float distance = glm::length(d);
  in.to_light = d / distance;
  float attenuation = lighting::light_attenuation(distance, *light.radius);
  if (light.kind == assets::LightKind::Spot) {
    const float cos_outer = std::cos(light.outer_cone), cos_inner = std::cos(light.inner_cone);
    const float scale = 1.0f / std::max(cos_inner - cos_outer, 1e-4f);
    const float cone = std::clamp(glm::dot(glm::normalize(light.direction), -in.to_light) * scale - cos_outer * scale, 0.0f, 1.0f);
    attenuation *= cone * cone;
  }
  in.radiance = light.color * light.intensity * attenuation;
  in.blocked = segment_hits_box(p, light.position, kWallMin, kWallMax);
  return in;
}

// Forward with one shadowed light, against the analytic picture: lit floor as
// the reference BRDF lights it, shadowed floor at the ambient term alone. The
// filter's penumbra (a few texels of the map, stretched where light grazes the
// floor) is left out: floor points whose neighbours `band` metres away
// disagree about the wall.
void expect_analytic_shadow(const assets::SceneLight& light, float band, bool glowing_wall = false) {
  const std::unique_ptr<World> world = wall_world(light, "forward", 1, glowing_wall);
  world->frame(0.0);
  const assets::Image image = world->renderer().read_output();
  const std::string name = "shadow_wall_" + std::to_string(static_cast<int>(light.kind)) + (glowing_wall ? "_glowing" : "");
  assets::write_png(name + ".png", image);
  // The analytic picture beside it, for a look (black: not compared).
  assets::Image expected_image{kSize.x, kSize.y, std::vector<std::uint8_t>(image.rgba.size(), 0)};
  EXPECT_EQ(world->renderer().stats().shadows.lights, 1u);
  const ViewState& view = world->registry().resource<ViewState>();
  int compared = 0, shadowed = 0, lit = 0, worst = 0;
  glm::ivec2 worst_pixel{0};
  glm::vec3 worst_point{0.0f};
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const auto hit = floor_point(view, x, kSize.y - 1 - y);
      if (!hit) continue;
      const glm::vec3 p = *hit;
      const Incoming in = incoming(light, p);
      bool edge = false;
      for (const glm::vec3 offset : {glm::vec3(band, 0, 0), glm::vec3(-band, 0, 0), glm::vec3(0, 0, band), glm::vec3(0, 0, -band)}) {
        edge = edge || incoming(light, p + offset).blocked != in.blocked;
      }
      if (edge) continue;
      const glm::vec3 v = glm::normalize(view.camera_position - p);
      glm::vec3 hdr = kAmbient * kFloor.albedo;
      if (!in.blocked) hdr += testing::reference_brdf(glm::vec3(0, 1, 0), v, in.to_light, kFloor) * in.radiance;
      const bool reached = glm::length(in.radiance) > 1e-3f;
      shadowed += in.blocked && reached;
      lit += !in.blocked && reached;
      for (int ch = 0; ch < 3; ++ch) {
        const int expected = static_cast<int>(std::lround(testing::reference_tonemap_to_srgb(hdr[ch] * kExposure) * 255.0));
        const int error = std::abs(expected - static_cast<int>(image.pixel(x, y)[ch]));
        if (error > worst) worst = error, worst_pixel = {x, y}, worst_point = p;
        expected_image.rgba[(static_cast<std::size_t>(y) * kSize.x + static_cast<std::size_t>(x)) * 4 + static_cast<std::size_t>(ch)] =
            static_cast<std::uint8_t>(expected);
      }
      expected_image.rgba[(static_cast<std::size_t>(y) * kSize.x + static_cast<std::size_t>(x)) * 4 + 3] = 255;
      ++compared;
    }
  }
  assets::write_png(name + "_expected.png", expected_image);
  EXPECT_GT(shadowed, 300) << "the wall's shadow should cover part of the floor in view";
  EXPECT_GT(lit, 300) << "the light should reach part of the floor in view";
  EXPECT_LE(worst, 2) << "largest channel error in 1/255 steps over " << compared << " floor pixels, at pixel (" << worst_pixel.x
                      << ", " << worst_pixel.y << "), floor point (" << worst_point.x << ", " << worst_point.z << ")";
}

// A warm point light of 12 m at `position`.
assets::SceneLight point_light(glm::vec3 position) {
  assets::SceneLight light;
  light.position = position;
  light.color = glm::vec3(1.0f, 0.9f, 0.8f);
  light.intensity = 6.0f;
  light.radius = 12.0f;
  return light;
}

TEST_F(Shadows, APointLightBehindAWallLeavesTheFarSideDark) {
  expect_analytic_shadow(point_light(glm::vec3(0.0f, 1.5f, -1.5f)), 0.15f);
}

TEST_F(Shadows, ASpotLightShadowsWhatItsConeReaches) {
  assets::SceneLight light;
  light.kind = assets::LightKind::Spot;
  light.position = glm::vec3(0.0f, 2.5f, -2.5f);
  light.direction = glm::normalize(glm::vec3(0.0f, -0.8f, 1.0f));
  light.inner_cone = 0.5f;
  light.outer_cone = 1.1f;
  light.color = glm::vec3(1.0f);
  light.intensity = 10.0f;
  light.radius = 14.0f;
  expect_analytic_shadow(light, 0.15f);
}

TEST_F(Shadows, ADirectionalLightsCascadesShadowTheFloor) {
  assets::SceneLight light;
  light.kind = assets::LightKind::Directional;
  light.direction = glm::normalize(glm::vec3(0.2f, -0.6f, 1.0f));
  light.color = glm::vec3(1.0f, 0.95f, 0.9f);
  light.intensity = 0.8f;
  // The far cascade's texels are about 4 cm and the light grazes the floor at 30 degrees.
  expect_analytic_shadow(light, 0.5f);
}

// Emissive surfaces cast shadows like any other, except from a light inside
// them: a lamp's glass around its own light.
TEST_F(Shadows, AGlowingWallShadowsALightOutsideIt) {
  expect_analytic_shadow(point_light(glm::vec3(0.0f, 1.5f, -1.5f)), 0.15f, true);
}

TEST_F(Shadows, AGlowingBoxAroundALightDoesNotShadowIt) {
  const assets::SceneLight light = point_light(glm::vec3(0.0f, 1.5f, 0.0f));  // inside the wall, which glows like lamp glass
  const std::unique_ptr<World> unshadowed = wall_world(light, "forward", 0, true);
  unshadowed->frame(0.0);
  const std::unique_ptr<World> shadowed = wall_world(light, "forward", 1, true);
  shadowed->frame(0.0);
  EXPECT_EQ(shadowed->renderer().stats().shadows.lights, 1u);
  const assets::Image image = shadowed->renderer().read_output();
  assets::write_png("shadow_lamp_glass.png", image);
  // Were the box a caster, it would enclose the light and darken the floor.
  EXPECT_GE(assets::psnr(unshadowed->renderer().read_output(), image), 50.0);
}

TEST_F(Shadows, EveryModeDrawsTheForwardPictureWithShadowsOn) {
  World world({.scene = "atrium", .lights = 48u, .mode = "forward", .size = {160, 90}});
  world.registry().resource<RendererSettings>().shadows = 12;
  for (const auto& info : techniques::technique_table()) {
    if (info.name == "forward") continue;
    testing::expect_forward_picture_from_every_view(world, std::string(info.name), "shadows_" + std::string(info.name));
  }
  EXPECT_EQ(world.renderer().stats().shadows.lights, 12u);
  // Light loops take the shadowed lights first (common/shading.glsl): they
  // lead the light buffer, each still the light of its own entity.
  const auto& lights = world.registry().resource<render::LightBuffer>();
  for (std::size_t i = 0; i < lights.staging.size(); ++i) {
    EXPECT_EQ(lights.staging[i].spot.z > 0.5f, i < 12u) << "light " << i;
    EXPECT_EQ(glm::vec3(lights.staging[i].position_radius), world.registry().get<Transform>(lights.entities[i]).position)
        << "light " << i;
  }
}

TEST_F(Shadows, ShadowsChangeThePictureOnlyWhereLightIsBlocked) {
  World world({.scene = "atrium", .lights = 48u, .mode = "forward", .size = {160, 90}});
  world.frame(0.0);
  const assets::Image unshadowed = world.renderer().read_output();
  world.registry().resource<RendererSettings>().shadows = 48;
  world.frame(0.0);
  const assets::Image shadowed = world.renderer().read_output();
  // Shadows only take light away.
  int darker = 0, brighter = 0;
  for (std::size_t i = 0; i < shadowed.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    brighter += shadowed.rgba[i] > unshadowed.rgba[i] + 1;
    darker += shadowed.rgba[i] + 8 < unshadowed.rgba[i];
  }
  EXPECT_EQ(brighter, 0);
  EXPECT_GT(darker, 500) << "columns and lamp posts should cast visible shadows";
}

TEST_F(Shadows, AMovingLightRedrawsOnlyItsOwnMaps) {
  World world({.scene = "atrium", .lights = 48u, .mode = "forward", .size = {160, 90}});
  world.registry().resource<RendererSettings>().shadows = 8;
  world.frame(0.0);
  const auto& stats = world.renderer().stats().shadows;
  EXPECT_EQ(stats.lights, 8u);
  EXPECT_GT(stats.maps_rendered, 0u);
  const std::size_t all_triangles = stats.triangles;
  EXPECT_GT(all_triangles, 0u);
  world.frame(0.0);
  EXPECT_EQ(stats.maps_rendered, 0u) << "nothing moved";
  EXPECT_EQ(stats.triangles, 0u) << "no map drawn";
  const std::uint32_t maps = stats.maps_reused;
  EXPECT_GE(maps, 8u);
  // Move one shadowed point light a little (its map keeps its size).
  const auto& lights = world.registry().resource<render::LightBuffer>();
  ecs::Entity moved;
  for (std::size_t i = 0; i < lights.staging.size(); ++i) {
    if (lights.staging[i].spot.z > 0.0f && lights.staging[i].color_kind.w == 0.0f) moved = lights.entities[i];
  }
  ASSERT_FALSE(moved.is_null());
  world.registry().get<Transform>(moved).position += glm::vec3(0.05f, 0.0f, 0.0f);
  world.frame(0.0);
  EXPECT_EQ(stats.maps_rendered, 6u) << "one point light's six faces";
  EXPECT_EQ(stats.maps_reused, maps - 6u);
  EXPECT_GT(stats.triangles, 0u);
  EXPECT_LT(stats.triangles, all_triangles) << "only its six faces drawn";
}

// The lights that have maps (their entities' indices).
std::set<std::uint32_t> shadowed_lights(World& world) {
  const auto& lights = world.registry().resource<render::LightBuffer>();
  std::set<std::uint32_t> shadowed;
  for (std::size_t i = 0; i < lights.staging.size(); ++i) {
    if (lights.staging[i].spot.z > 0.0f) shadowed.insert(lights.entities[i].index);
  }
  return shadowed;
}

// Lights shadowed last frame keep their maps over slightly brighter ones, so
// that shadows do not flicker as the camera moves; after a jump to a stored
// view (a camera cut) the maps go where a camera that started there puts them.
TEST_F(Shadows, AfterACameraCutTheMapsGoWhereAFreshStartPutsThem) {
  auto with_shadows = [](int view) {
    auto world = std::make_unique<World>(WorldOptions{.scene = "atrium", .lights = 48u, .mode = "forward", .view = view, .size = {160, 90}});
    world->registry().resource<RendererSettings>().shadows = 4;
    world->frame(0.0);
    return world;
  };
  // Four of these six jumps kept some of the last view's maps while the
  // choice remembered them across the cut.
  const std::unique_ptr<World> world = with_shadows(1);
  int from = 1;
  for (const int to : {4, 1, 3, 4, 5, 3}) {
    world->frame(0.0);
    world->set_view(to);
    world->frame(0.0);
    EXPECT_EQ(shadowed_lights(*world), shadowed_lights(*with_shadows(to))) << "from view " << from << " to view " << to;
    from = to;
  }
}

TEST_F(Shadows, MovingGeometryRedrawsTheMapsItReaches) {
  World world({.scene = "atrium", .lights = 48u, .mode = "forward", .size = {160, 90}});
  world.registry().resource<RendererSettings>().shadows = 8;
  world.frame(0.0);
  world.frame(0.0);
  const auto& stats = world.renderer().stats().shadows;
  ASSERT_EQ(stats.maps_rendered, 0u);
  // Lift every mesh instance: every map sees geometry move.
  world.registry().view<Transform, MeshInstance>().each([](Transform& t, const MeshInstance&) { t.position.y += 0.01f; });
  world.frame(0.0);
  EXPECT_EQ(stats.maps_reused, 0u);
  EXPECT_GT(stats.maps_rendered, 0u);
}

// The atlas moves shadowed lights to the front of the light buffer each
// frame; with shadows off the buffer holds the lights in their own order
// again, though no light moved, and draws the picture it drew before them.
TEST_F(Shadows, OffPutsTheLightsBackInTheirOwnOrder) {
  World world({.scene = "atrium", .lights = 48u, .mode = "clustered-deferred", .size = {160, 90}});
  world.frame(0.0);
  const assets::Image before = world.renderer().read_output();
  auto& settings = world.registry().resource<RendererSettings>();
  settings.shadows = 8;
  world.frame(0.0);
  world.frame(0.0);
  settings.shadows = 0;
  world.frame(0.0);
  const auto& lights = world.registry().resource<render::LightBuffer>();
  const render::GatheredLights own = render::gather_lights(world.registry());
  ASSERT_EQ(lights.staging.size(), own.lights.size());
  const std::vector<render::GpuLight> held = testing::read_back_lights(lights);
  for (std::size_t i = 0; i < held.size(); ++i) {
    ASSERT_EQ(lights.entities[i], own.entities[i]) << "light " << i;
    ASSERT_EQ(std::memcmp(&held[i], &own.lights[i], sizeof(render::GpuLight)), 0) << "light " << i;
  }
  EXPECT_EQ(assets::max_channel_difference(world.renderer().read_output(), before), 0);
}

TEST_F(Shadows, OffGivesTheAtlasBack) {
  World world({.scene = "atrium", .lights = 16u, .mode = "deferred", .size = {64, 36}});
  auto& settings = world.registry().resource<RendererSettings>();
  settings.shadows = 4;
  world.frame(0.0);
  EXPECT_NE(world.renderer().shadow_atlas().texture(), 0u);
  settings.shadows = 0;
  world.frame(0.0);
  EXPECT_EQ(world.renderer().shadow_atlas().texture(), 0u);
  EXPECT_EQ(world.renderer().stats().shadows.atlas_size, 0);
}

// --- CPU parts ---

TEST(AtlasAllocator, TilesNeverOverlapAndFreedTilesMergeBack) {
  shadows::AtlasAllocator atlas(1024, 32);
  std::vector<shadows::AtlasTile> tiles;
  for (int size : {256, 32, 512, 64, 64, 128, 32}) {
    const auto tile = atlas.allocate(size);
    ASSERT_TRUE(tile) << size;
    EXPECT_EQ(tile->size, size);
    EXPECT_EQ(tile->origin.x % size, 0);
    EXPECT_EQ(tile->origin.y % size, 0);
    for (const auto& other : tiles) {
      const bool apart = tile->origin.x + size <= other.origin.x || other.origin.x + other.size <= tile->origin.x ||
                         tile->origin.y + size <= other.origin.y || other.origin.y + other.size <= tile->origin.y;
      EXPECT_TRUE(apart);
    }
    tiles.push_back(*tile);
  }
  for (const auto& tile : tiles) atlas.release(tile);
  EXPECT_EQ(atlas.free_texels(), 1024LL * 1024);
  EXPECT_TRUE(atlas.allocate(1024)) << "the quarters merged back into the whole atlas";
  EXPECT_FALSE(atlas.allocate(32)) << "full";
  EXPECT_FALSE(atlas.allocate(48)) << "not a power of two";
}

TEST(AtlasAllocator, TilesThatFitByAreaPackLargestFirst) {
  shadows::AtlasAllocator atlas(512, 32);
  // 1 x 256^2 + 32 x 64^2 + 64 x 32^2 = 512^2 exactly.
  std::vector<int> sizes{256};
  for (int i = 0; i < 32; ++i) sizes.push_back(64);
  for (int i = 0; i < 64; ++i) sizes.push_back(32);
  for (int size : sizes) ASSERT_TRUE(atlas.allocate(size)) << size;
  EXPECT_EQ(atlas.free_texels(), 0);
}

render::GpuLight point_light(glm::vec3 position, float radius, float brightness) {
  return {glm::vec4(position, radius), glm::vec4(glm::vec3(brightness), 0.0f), glm::vec4(0, 0, -1, 0), glm::vec4(0.0f)};
}

ViewState camera_at_origin() {
  ViewState view;
  view.projection = gfx::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f);
  view.view = glm::mat4(1.0f);  // looking down -Z
  view.view_projection = view.projection * view.view;
  return view;
}

TEST(ShadowSelection, TheBrightestNearestLightsInViewWinAndDirectionalComesFirst) {
  std::vector<render::GpuLight> lights{point_light({0, 0, -5}, 3, 1.0f),     // in view, near
                               point_light({0, 0, -40}, 3, 1.0f),    // in view, far
                               point_light({0, 0, 20}, 3, 50.0f),    // behind the camera: no pixel of it shows
                               point_light({1, 0, -5}, 3, 4.0f)};    // as near, brighter
  render::GpuLight sun{glm::vec4(0.0f), glm::vec4(glm::vec3(0.1f), 2.0f), glm::vec4(0, -1, 0, 0), glm::vec4(0.0f)};
  lights.push_back(sun);
  std::vector<ecs::Entity> entities;
  for (std::uint32_t i = 0; i < lights.size(); ++i) entities.push_back({i, 0});
  const auto choices = shadows::choose_shadowed_lights(lights, entities, camera_at_origin(), {1280, 720}, 3, {}, {});
  ASSERT_EQ(choices.size(), 3u);
  EXPECT_EQ(choices[0].light, 4u) << "the directional light";
  EXPECT_EQ(choices[1].light, 3u);
  EXPECT_EQ(choices[2].light, 0u);
  EXPECT_GT(choices[1].resolution, 32) << "a light filling much of the screen gets a large map";
}

TEST(ShadowSelection, AShadowedLightKeepsItsPlaceOverOneSlightlyBrighter) {
  std::vector<render::GpuLight> lights{point_light({-1, 0, -8}, 3, 1.0f), point_light({1, 0, -8}, 3, 1.2f)};
  std::vector<ecs::Entity> entities{{0, 0}, {1, 0}};
  const ViewState view = camera_at_origin();
  auto choices = shadows::choose_shadowed_lights(lights, entities, view, {1280, 720}, 1, {}, {});
  ASSERT_EQ(choices.size(), 1u);
  EXPECT_EQ(choices[0].light, 1u);
  // Light 0 held the map last frame: 1.2x is within the bonus, so it keeps it.
  shadows::PreviousShadows previous{{entities[0], choices[0].resolution}};
  choices = shadows::choose_shadowed_lights(lights, entities, view, {1280, 720}, 1, previous, {});
  EXPECT_EQ(choices[0].light, 0u);
  // At twice the brightness the other light wins.
  lights[1].color_kind = glm::vec4(glm::vec3(2.0f), 0.0f);
  choices = shadows::choose_shadowed_lights(lights, entities, view, {1280, 720}, 1, previous, {});
  EXPECT_EQ(choices[0].light, 1u);
}

// A light the GPU moves is ranked from its record, which holds its origin:
// one whose origin sphere lies just outside the view but whose circle brings
// it in is still a candidate, as a light standing there is not.
TEST(ShadowSelection, ALightTheGpuMovesIntoViewIsACandidate) {
  const ViewState view = camera_at_origin();
  const glm::vec3 origin(7.0f, 0.0f, -5.0f);
  const render::GpuLight still = point_light(origin, 1.0f, 1.0f);
  // Phase 0: half a turn on, the light is a diameter (1 m) nearer the view's axis.
  const LightAnimation motion{origin, 0.0f, 0.5f, 0.6f};
  const render::GpuLight moving = render::with_motion(still, motion);
  const Frustum frustum = frustum_of(view.view_projection);
  ASSERT_FALSE(intersects(frustum, origin, 1.0f)) << "the origin's sphere is out of view";
  ASSERT_TRUE(intersects(frustum, render::moved_position(moving, glm::pi<double>() / motion.angular_speed), 1.0f))
      << "the light moves into view";

  const std::vector<ecs::Entity> entities{{0, 0}};
  EXPECT_TRUE(shadows::choose_shadowed_lights(std::vector{still}, entities, view, {1280, 720}, 1, {}, {}).empty());
  const auto choices = shadows::choose_shadowed_lights(std::vector{moving}, entities, view, {1280, 720}, 1, {}, {});
  ASSERT_EQ(choices.size(), 1u);
  EXPECT_EQ(choices[0].light, 0u);
}

TEST(ShadowSelection, MapsShrinkToFitTheAtlas) {
  std::vector<render::GpuLight> lights;
  std::vector<ecs::Entity> entities;
  for (std::uint32_t i = 0; i < 64; ++i) {
    lights.push_back(point_light({static_cast<float>(i % 8) - 4.0f, static_cast<float>(i / 8) - 4.0f, -6.0f}, 5, 1.0f));
    entities.push_back({i, 0});
  }
  const shadows::AtlasLimits limits{1024, 32, 512};
  const auto choices = shadows::choose_shadowed_lights(lights, entities, camera_at_origin(), {1920, 1080}, 64, {}, limits);
  long long area = 0;
  for (const auto& c : choices) area += 6LL * c.resolution * c.resolution;
  EXPECT_LE(area, 1024LL * 1024);
  EXPECT_EQ(choices.size(), 64u) << "64 lights x 6 faces x 32^2 fit in 1024^2";
}

}  // namespace
}  // namespace atrium
