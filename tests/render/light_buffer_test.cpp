#include <cstring>
#include <functional>
#include <thread>
#include <limits>

#include <gmock/gmock.h>

#include "components/light.hpp"
#include "components/transform.hpp"
#include "ecs/scheduler.hpp"
#include "support/gl_test.hpp"
#include "support/light_buffer_read_back.hpp"
#include "render/light_buffer.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium {
namespace {

using LightBufferSystem = testing::GlTest;

ecs::Entity add_light(ecs::Registry& registry, glm::vec3 position, glm::vec3 color, float intensity) {
  const ecs::Entity e = registry.create();
  registry.add<Transform>(e, Transform{position});
  registry.add<LightColor>(e, color, intensity);
  return e;
}

TEST_F(LightBufferSystem, MirrorsLightEntitiesWithGivenOrDerivedRadii) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  const ecs::Entity a = add_light(registry, {1, 2, 3}, {1.0f, 0.5f, 0.25f}, 2.0f);
  const ecs::Entity b = add_light(registry, {-4, 5, 6}, {0.2f, 0.4f, 0.8f}, 1.0f);
  registry.add<LightRadius>(b, 2.5f);
  const ecs::Entity not_a_light = registry.create();
  registry.add<Transform>(not_a_light);
  scheduler.run_frame(registry, 0.0);

  const auto lights = testing::read_back_lights(registry.resource<render::LightBuffer>());
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(glm::vec3(lights[0].position_radius), glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(lights[0].position_radius.w, lighting::light_radius_from_intensity({1.0f, 0.5f, 0.25f}, 2.0f));
  EXPECT_EQ(glm::vec3(lights[0].color_kind), glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_EQ(lights[0].color_kind.w, static_cast<float>(render::GpuLightKind::Point));
  EXPECT_FLOAT_EQ(lights[1].position_radius.w, 2.5f);

  // Changes to the entities show up in the next frame.
  registry.get<Transform>(a).position = {7, 8, 9};
  registry.destroy(b);
  scheduler.run_frame(registry, 0.0);
  const auto after = testing::read_back_lights(registry.resource<render::LightBuffer>());
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(glm::vec3(after[0].position_radius), glm::vec3(7, 8, 9));
}

// A frame sends only the lights that changed: none while they hold still (the
// bench's frames, a paused animation), one run for one moved light; what the
// GPU holds is every light all the same.
TEST_F(LightBufferSystem, SendsOnlyTheLightsThatChanged) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  std::vector<ecs::Entity> lights;
  for (int i = 0; i < 1000; ++i) lights.push_back(add_light(registry, {static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f));
  scheduler.run_frame(registry, 0.0);
  const render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  EXPECT_EQ(buffer.uploaded, 1000u);
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 0u) << "lights that hold still are not sent again";
  registry.get<Transform>(lights[500]).position.y = 3.0f;
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 1u);
  EXPECT_EQ(testing::read_back_lights(buffer)[500].position_radius.y, 3.0f);
  // Two lights far apart go as two runs, not everything between them.
  registry.get<LightColor>(lights[10]).intensity = 2.0f;
  registry.get<LightColor>(lights[900]).intensity = 2.0f;
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 2u);
  const auto after = testing::read_back_lights(buffer);
  EXPECT_EQ(after[10].color_kind.x, 2.0f);
  EXPECT_EQ(after[900].color_kind.x, 2.0f);
  EXPECT_EQ(after[899].color_kind.x, 1.0f);
}

TEST_F(LightBufferSystem, HasNoCapOnTheNumberOfLights) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  add_light(registry, {0, 0, 0}, {1, 1, 1}, 1.0f);
  scheduler.run_frame(registry, 0.0);
  for (int i = 1; i < 100'000; ++i) add_light(registry, {static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f);
  scheduler.run_frame(registry, 0.0);
  const render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  EXPECT_EQ(buffer.count, 100'000u);
  EXPECT_GE(buffer.capacity, 100'000u);
  const auto lights = testing::read_back_lights(buffer);
  EXPECT_EQ(lights.back().position_radius.x, 99'999.0f);
  // Gathered in chunks on several threads, in the registry's order all the same.
  for (std::size_t i = 0; i < lights.size(); ++i) ASSERT_EQ(lights[i].position_radius.x, static_cast<float>(i)) << i;
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 0u);
}

TEST_F(LightBufferSystem, SpotAndDirectionalLightsCarryTheirKindDirectionAndCone) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  const ecs::Entity spot = add_light(registry, {0, 5, 0}, {1, 1, 1}, 4.0f);
  registry.get<Transform>(spot).rotation = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));  // -Z turned to -Y
  registry.add<SpotCone>(spot, 0.2f, 0.5f);
  const ecs::Entity sun = add_light(registry, {0, 0, 0}, {1, 0.9f, 0.8f}, 3.0f);
  registry.add<DirectionalLight>(sun);
  scheduler.run_frame(registry, 0.0);
  const auto lights = testing::read_back_lights(registry.resource<render::LightBuffer>());
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].color_kind.w, static_cast<float>(render::GpuLightKind::Spot));
  EXPECT_NEAR(lights[0].direction.y, -1.0f, 1e-6f);
  const float scale = 1.0f / (std::cos(0.2f) - std::cos(0.5f));
  EXPECT_NEAR(lights[0].spot.x, scale, 1e-3f);
  EXPECT_NEAR(lights[0].spot.y, -std::cos(0.5f) * scale, 1e-3f);
  EXPECT_EQ(lights[1].color_kind.w, static_cast<float>(render::GpuLightKind::Directional));
  EXPECT_EQ(lights[1].position_radius.w, 0.0f);
}

TEST_F(LightBufferSystem, LightsASystemBrokeAreLeftOutWithOneWarningNamingThem) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();
  add_light(registry, {0, 1, 0}, {1, 1, 1}, 1.0f);
  const ecs::Entity nan_position = add_light(registry, {kNan, 0, 0}, {1, 1, 1}, 1.0f);
  add_light(registry, {0, 0, 0}, {1, 1, 1}, kInf);
  add_light(registry, {0, 0, 0}, {1, 1, 1}, -2.0f);
  add_light(registry, {0, 0, 0}, {1, -1, 1}, 1.0f);
  registry.add<LightRadius>(add_light(registry, {0, 0, 0}, {1, 1, 1}, 1.0f), 0.0f);
  registry.add<LightRadius>(add_light(registry, {0, 0, 0}, {1, 1, 1}, 1.0f), kNan);
  const ecs::Entity sun = add_light(registry, {kInf, 0, 0}, {1, 1, 1}, 1.0f);
  registry.add<DirectionalLight>(sun);  // a direction has no position to break

  const render::GatheredLights gathered = render::gather_lights(registry);
  EXPECT_EQ(gathered.lights.size(), 2u);
  ASSERT_EQ(gathered.rejected.size(), 6u);
  EXPECT_EQ(gathered.rejected[0].entity, nan_position);
  EXPECT_THAT(gathered.rejected[0].problem, ::testing::HasSubstr("position (nan, 0, 0) is not finite"));
  EXPECT_THAT(gathered.rejected[1].problem, ::testing::HasSubstr("intensity inf"));
  EXPECT_THAT(gathered.rejected[2].problem, ::testing::HasSubstr("intensity -2"));
  EXPECT_THAT(gathered.rejected[3].problem, ::testing::HasSubstr("colour (1, -1, 1)"));
  EXPECT_THAT(gathered.rejected[4].problem, ::testing::HasSubstr("radius 0"));
  EXPECT_THAT(gathered.rejected[5].problem, ::testing::HasSubstr("radius nan"));

  ::testing::internal::CaptureStderr();
  scheduler.run_frame(registry, 0.0);
  scheduler.run_frame(registry, 0.0);
  const std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(registry.resource<render::LightBuffer>().count, 2u);
  EXPECT_EQ(registry.resource<render::LightBuffer>().rejected, 6u);
  EXPECT_EQ(std::count(warnings.begin(), warnings.end(), '\n'), 6) << "one warning per light, not per frame:\n" << warnings;
  EXPECT_THAT(warnings, ::testing::HasSubstr("warning: light entity " + std::to_string(nan_position.index) + " left out: position"));
}

// The buffer against gather_lights, the plain one-thread walk, light by light.
void expect_buffer_matches_gather(ecs::Registry& registry, const char* step) {
  const render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  const std::vector<render::GpuLight> expected = render::gather_lights(registry).lights;
  const std::vector<render::GpuLight> held = testing::read_back_lights(buffer);
  ASSERT_EQ(held.size(), expected.size()) << step;
  for (std::size_t i = 0; i < held.size(); ++i) {
    ASSERT_EQ(std::memcmp(&held[i], &expected[i], sizeof(render::GpuLight)), 0) << step << ": light " << i;
  }
}

// Each thread writes its share of the pool where last frame's share began; a
// light rejected, mended or destroyed before a share moves it, and that frame
// must still send every light to its place.
TEST_F(LightBufferSystem, LightsLeftOutOrBackMoveTheLightsAfterThemIntoPlace) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  std::vector<ecs::Entity> lights;
  for (int i = 0; i < 40'000; ++i) lights.push_back(add_light(registry, {static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f));
  scheduler.run_frame(registry, 0.0);
  const render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  expect_buffer_matches_gather(registry, "first frame");

  ::testing::internal::CaptureStderr();
  registry.get<Transform>(lights[10]).position.x = std::numeric_limits<float>::quiet_NaN();
  scheduler.run_frame(registry, 0.0);
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), ::testing::HasSubstr("left out: position (nan"));
  EXPECT_EQ(buffer.count, 39'999u);
  expect_buffer_matches_gather(registry, "light 10 left out");
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 0u) << "steady again after the shift";

  registry.get<Transform>(lights[10]).position.x = 10.0f;
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.count, 40'000u);
  expect_buffer_matches_gather(registry, "light 10 back");

  registry.get<Transform>(lights[30'000]).position.y = 2.0f;
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.uploaded, 1u) << "a light moved in a later share goes alone";
  expect_buffer_matches_gather(registry, "light 30,000 moved");

  registry.destroy(lights[5]);  // the pool's last light takes its slot
  for (int i = 0; i < 100; ++i) add_light(registry, {-1.0f - static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f);
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.count, 40'099u);
  expect_buffer_matches_gather(registry, "a light destroyed, a hundred added");
}

// Lights that hold still are not walked at all: the registry's change
// detection tells the buffer which blocks of lights something wrote, through
// any of the ways a system writes components, and those alone are walked.
TEST_F(LightBufferSystem, WalksOnlyTheLightsSomethingWrote) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  constexpr std::uint32_t kLights = 40'000;
  std::vector<ecs::Entity> lights;
  for (std::uint32_t i = 0; i < kLights; ++i) lights.push_back(add_light(registry, {static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f));
  registry.add<LightRadius>(lights[20'000], 3.0f);
  scheduler.run_frame(registry, 0.0);
  const render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  EXPECT_EQ(buffer.walked, kLights);
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.walked, 0u) << "nothing wrote a light";
  EXPECT_EQ(buffer.uploaded, 0u);

  struct Write {
    const char* how;
    std::function<void()> write;
  };
  const std::vector<Write> writes = {
      {"get<Transform>", [&] { registry.get<Transform>(lights[100]).position.y = 1.0f; }},
      {"try_get<LightColor>", [&] { registry.try_get<LightColor>(lights[39'999])->intensity = 2.0f; }},
      {"get<LightRadius>", [&] { registry.get<LightRadius>(lights[20'000]).radius = 4.0f; }},
      {"a view's Transform&", [&] {
         registry.view<Transform, LightRadius>().each([](Transform& t, const LightRadius&) { t.position.z = 2.0f; });
       }},
      {"Lookup<Transform> on another thread", [&] {
         std::thread([&] { registry.lookup<Transform>().find(lights[30'500])->position.x = -5.0f; }).join();
       }},
      {"add over a LightColor", [&] { registry.add<LightColor>(lights[7], glm::vec3(0.5f), 1.0f); }},
  };
  for (const Write& w : writes) {
    w.write();
    scheduler.run_frame(registry, 0.0);
    EXPECT_GT(buffer.walked, 0u) << w.how;
    EXPECT_LE(buffer.walked, 2048u) << w.how << ": its block of lights, and a neighbour whose components share its pool's stamp";
    EXPECT_EQ(buffer.uploaded, 1u) << w.how;
    expect_buffer_matches_gather(registry, w.how);
  }
  // A light made unfit moves every light after it in its share; the walk goes on past its block.
  registry.get<LightColor>(lights[5]).intensity = -1.0f;
  ::testing::internal::CaptureStderr();
  scheduler.run_frame(registry, 0.0);
  ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(buffer.count, kLights - 1);
  expect_buffer_matches_gather(registry, "light 5 left out");
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.walked, 0u) << "still again";
  EXPECT_EQ(buffer.rejected, 1u) << "the light left out is still counted";
  // Adding a component walks every light (the pools' structure changed).
  registry.add<SpotCone>(lights[12'345]);
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(buffer.walked, kLights);
  expect_buffer_matches_gather(registry, "a spot cone added");
}

// A later system of the frame may change the staging copy (the ShadowAtlas
// moves shadowed lights to the front and notes where): the next frame puts
// those lights back though nothing wrote them.
TEST_F(LightBufferSystem, PutsBackWhatALaterSystemPatched) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  for (int i = 0; i < 5'000; ++i) add_light(registry, {static_cast<float>(i), 0, 0}, {1, 1, 1}, 1.0f);
  scheduler.run_frame(registry, 0.0);
  render::LightBuffer& buffer = registry.resource<render::LightBuffer>();
  std::swap(buffer.staging[0], buffer.staging[4'000]);
  std::swap(buffer.entities[0], buffer.entities[4'000]);
  buffer.staging[0].spot.z = 1.0f;
  glNamedBufferSubData(buffer.buffer.id(), 0, static_cast<GLsizeiptr>(buffer.staging.size() * sizeof(render::GpuLight)), buffer.staging.data());
  buffer.patched = {0, 4'000};
  scheduler.run_frame(registry, 0.0);
  EXPECT_LE(buffer.walked, 2'048u) << "the two patched lights' blocks";
  expect_buffer_matches_gather(registry, "after the patch");
  EXPECT_TRUE(buffer.patched.empty());
}

// A point light that moves on the GPU carries its motion in its record, and
// a motion that cannot be drawn leaves the light out, saying why.
TEST_F(LightBufferSystem, APointLightMovedOnTheGpuCarriesItsMotion) {
  ecs::Registry registry;
  registry.set_resource<LightAnimationSettings>().on_gpu = true;
  const ecs::Entity moving = add_light(registry, {1, 2, 3}, {1, 1, 1}, 1.0f);
  registry.add<LightAnimation>(moving, glm::vec3(1, 2, 3), 0.25f, 0.5f, 0.6f);
  const ecs::Entity spot = add_light(registry, {0, 1, 0}, {1, 1, 1}, 1.0f);
  registry.add<SpotCone>(spot);
  registry.add<LightAnimation>(spot, glm::vec3(0, 1, 0));
  const ecs::Entity broken = add_light(registry, {0, 1, 0}, {1, 1, 1}, 1.0f);
  registry.add<LightAnimation>(broken, glm::vec3(0, 1, 0), std::numeric_limits<float>::quiet_NaN());

  const render::GatheredLights gathered = render::gather_lights(registry);
  ASSERT_EQ(gathered.lights.size(), 2u);
  const render::GpuLight& light = gathered.lights[0];
  EXPECT_TRUE(render::moves_on_gpu(light));
  EXPECT_EQ(light.direction, glm::vec4(1, 2, 3, 0.5f));
  EXPECT_EQ(glm::vec2(light.spot), glm::vec2(0.25f, 0.6f));
  EXPECT_EQ(render::moved_position(light, 2.0), animated_position(registry.get<LightAnimation>(moving), 2.0));
  EXPECT_EQ(render::motion_reach(light), animated_reach(registry.get<LightAnimation>(moving)));
  EXPECT_FALSE(render::moves_on_gpu(gathered.lights[1])) << "a spot light moves on the CPU";
  EXPECT_EQ(render::motion_reach(gathered.lights[1]), 0.0f) << "the record holds where the CPU put it";
  ASSERT_EQ(gathered.rejected.size(), 1u);
  EXPECT_THAT(gathered.rejected[0].problem, ::testing::HasSubstr("animation (origin (0, 1, 0), radius 0.5, phase nan"));

  registry.resource<LightAnimationSettings>().on_gpu = false;
  EXPECT_FALSE(render::moves_on_gpu(render::gather_lights(registry).lights[0])) << "off the GPU tier the record is a plain light";
}

TEST_F(LightBufferSystem, ZeroLightsIsValid) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  render::register_light_buffer(scheduler);
  scheduler.run_frame(registry, 0.0);
  EXPECT_EQ(registry.resource<render::LightBuffer>().count, 0u);
  EXPECT_NE(registry.resource<render::LightBuffer>().buffer.id(), 0u);
}

}  // namespace
}  // namespace atrium
