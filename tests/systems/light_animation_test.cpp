// The light animation on the GPU (systems/light_animation.cpp): where the
// context runs compute shaders, point lights move in a pass of the light
// animation system, from the motion the LightBuffer sent once. The GPU puts
// each light where the CPU's animation would; every mode draws the moved
// lights as it draws lights placed there by hand, shadows included; and the
// CPU sends and walks nothing while they move.
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "base/golden_angle.hpp"
#include "assets/image.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "render/light_buffer.hpp"
#include "support/gl_test.hpp"
#include "support/light_buffer_read_back.hpp"
#include "support/modes.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

using testing::kSize;
using LightAnimationOnGpu = testing::GlTest;

constexpr double kStep = 0.5;  // seconds a frame
constexpr int kFrames = 6;     // 3 s in: the lights are a turn's third round their circles

WorldOptions options_for(const std::string& mode, int shadows = 0) {
  WorldOptions options;
  options.size = kSize;
  options.mode = mode;
  options.lights = 32;
  options.light_radius = 8.0f;  // pools of light that show where each light is
  options.shadows = shadows;
  return options;
}

// The built-in scene's point lights animated as the World animates generated
// ones (a scene file's or a model's): from where they are, phases spread.
void animate_point_lights(World& world) {
  ecs::Registry& registry = world.registry();
  std::vector<ecs::Entity> lights(registry.entities_with<LightColor>().begin(), registry.entities_with<LightColor>().end());
  std::uint64_t k = 0;
  for (const ecs::Entity e : lights) {
    if (registry.has<SpotCone>(e) || registry.has<DirectionalLight>(e)) continue;
    // Circles of 2 m, so that three seconds change the picture plainly.
    registry.add<LightAnimation>(e, registry.get<Transform>(e).position, golden_angle_phase(k++), 2.0f);
  }
}

// The world as the window runs it: the light animation registered, kFrames frames.
void run_animated(World& world) {
  register_light_animation(world.scheduler(), world.registry());
  for (int f = 0; f < kFrames; ++f) world.frame(kStep);
}

// The same lights held still where the animation puts them kFrames frames
// in: no LightAnimation, placed by their Transforms (the path every light
// without one takes).
void place_by_hand(World& world) {
  ecs::Registry& registry = world.registry();
  std::vector<ecs::Entity> animated(registry.entities_with<LightAnimation>().begin(), registry.entities_with<LightAnimation>().end());
  for (const ecs::Entity e : animated) {
    registry.get<Transform>(e).position = animated_position(registry.get<LightAnimation>(e), kStep * kFrames);
    registry.remove<LightAnimation>(e);
  }
  world.frame(0.0);
}

// Every light the GPU holds is where the CPU's animation puts it at `time`
// (or where its Transform is, for one that does not move); returns how many
// of the animated ones are a good way from their origins.
std::size_t expect_lights_at(const ecs::Registry& registry, double time) {
  const auto& buffer = registry.resource<render::LightBuffer>();
  const std::vector<render::GpuLight> lights = testing::read_back_lights(buffer);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const ecs::Entity e = buffer.entities[i];
    const auto* animation = registry.try_get<LightAnimation>(e);
    const glm::vec3 expected = animation ? animated_position(*animation, time) : registry.try_get<Transform>(e)->position;
    EXPECT_LT(glm::distance(glm::vec3(lights[i].position_radius), expected), 1e-4f) << "light " << i;
    if (animation && glm::distance(expected, animation->origin) > 0.1f) ++moved;
  }
  return moved;
}

bool ran_motion_pass(World& world) {
  for (const render::CompiledPass& pass : world.renderer().graph().passes()) {
    if (pass.name == "light motion") return !pass.culled;
  }
  return false;
}

TEST_F(LightAnimationOnGpu, PutsEveryLightWhereTheCpuWouldAndCostsTheCpuNothing) {
  World world(options_for("clustered-deferred"));
  animate_point_lights(world);
  ASSERT_TRUE(world.registry().resource<LightAnimationSettings>().on_gpu) << "llvmpipe runs compute shaders";
  std::vector<glm::vec3> origins;
  for (const ecs::Entity e : world.registry().entities_with<LightAnimation>()) origins.push_back(world.registry().get<Transform>(e).position);
  ASSERT_EQ(origins.size(), 32u);
  run_animated(world);

  const ecs::Registry& registry = world.registry();
  const double time = registry.resource<LightAnimationSettings>().time;
  ASSERT_DOUBLE_EQ(time, kStep * kFrames);
  EXPECT_GE(expect_lights_at(registry, time), 28u) << "three seconds move the lights a good way round their circles";
  std::size_t index = 0;
  for (const ecs::Entity e : registry.entities_with<LightAnimation>()) {
    EXPECT_EQ(registry.try_get<Transform>(e)->position, origins[index++]) << "the CPU leaves a point light's Transform at its origin";
  }
  const auto& buffer = registry.resource<render::LightBuffer>();
  EXPECT_EQ(buffer.uploaded, 0u) << "moving lights send nothing after the first frame";
  EXPECT_EQ(buffer.walked, 0u) << "nor does the CPU walk them";
}

// Paused (`p`), the lights stay where they stopped and the pass does not run:
// the buffer still holds what it wrote. A record sent again (a light edited)
// starts from its origin, so that frame runs it again; so does the clock.
TEST_F(LightAnimationOnGpu, APausedClockSkipsThePassUntilALightIsSentAgain) {
  World world(options_for("clustered-deferred"));
  animate_point_lights(world);
  run_animated(world);
  ASSERT_TRUE(ran_motion_pass(world));
  const assets::Image moving = world.renderer().read_output();
  ecs::Registry& registry = world.registry();
  auto& settings = registry.resource<LightAnimationSettings>();
  settings.paused = true;
  const double stopped = settings.time;

  world.frame(kStep);
  EXPECT_FALSE(ran_motion_pass(world)) << "nothing moved: no pass over every light";
  EXPECT_GE(expect_lights_at(registry, stopped), 28u);
  EXPECT_EQ(assets::psnr(moving, world.renderer().read_output()), std::numeric_limits<double>::infinity()) << "the lights held where they stopped";

  const ecs::Entity edited = registry.entities_with<LightAnimation>()[3];
  registry.get<LightColor>(edited).intensity *= 1.5f;
  world.frame(kStep);
  EXPECT_GT(registry.resource<render::LightBuffer>().uploaded, 0u);
  EXPECT_TRUE(ran_motion_pass(world)) << "the edited light's record came back at its origin";
  expect_lights_at(registry, stopped);
  world.frame(kStep);
  EXPECT_FALSE(ran_motion_pass(world));

  settings.paused = false;
  world.frame(kStep);
  EXPECT_TRUE(ran_motion_pass(world));
  expect_lights_at(registry, stopped + kStep);
}

// Spot and directional lights move on the CPU: where only they animate, no
// pass runs over every light record for nothing.
TEST_F(LightAnimationOnGpu, OnlySpotLightsAnimatingRunNoPassOverEveryLight) {
  World world(options_for("clustered-deferred"));
  ecs::Registry& registry = world.registry();
  // The generated point lights hold still: they animate by default.
  std::vector<ecs::Entity> animated(registry.entities_with<LightAnimation>().begin(), registry.entities_with<LightAnimation>().end());
  for (const ecs::Entity e : animated) registry.remove<LightAnimation>(e);
  const ecs::Entity spot = registry.create();
  const glm::vec3 origin(0.0f, 3.0f, 0.0f);
  registry.add<Transform>(spot, Transform{origin});
  registry.add<LightColor>(spot, LightColor{glm::vec3(1.0f), 4.0f});
  registry.add<SpotCone>(spot);
  registry.add<LightAnimation>(spot, origin, 0.0f, 2.0f);
  ASSERT_TRUE(registry.resource<LightAnimationSettings>().on_gpu);
  register_light_animation(world.scheduler(), registry);
  for (int f = 0; f < kFrames; ++f) {
    world.frame(kStep);
    EXPECT_FALSE(ran_motion_pass(world)) << "frame " << f;
  }
  EXPECT_GT(glm::distance(registry.get<Transform>(spot).position, origin), 0.5f) << "the CPU moved the spot light";
  expect_lights_at(registry, kStep * kFrames);

  animate_point_lights(world);
  world.frame(kStep);
  EXPECT_TRUE(ran_motion_pass(world)) << "point lights animate too: the GPU moves them";
  expect_lights_at(registry, kStep * (kFrames + 1));
}

// Moved on the GPU against held still where the CPU's animation puts them:
// the same picture in every mode, and not the picture before they moved.
void expect_moved_as_placed(const std::vector<std::string>& modes, int shadows) {
  World at_rest(options_for("forward", shadows));
  at_rest.frame(0.0);
  const assets::Image before = at_rest.renderer().read_output();
  for (const std::string& mode : modes) {
    World moving(options_for(mode, shadows));
    animate_point_lights(moving);
    run_animated(moving);
    const assets::Image moved = moving.renderer().read_output();
    World placed(options_for(mode, shadows));
    animate_point_lights(placed);
    place_by_hand(placed);
    const assets::Image by_hand = placed.renderer().read_output();
    const std::string name = "light_animation_" + mode + (shadows > 0 ? "_shadows" : "");
    assets::write_png(name + "_gpu.png", moved);
    assets::write_png(name + "_cpu.png", by_hand);
    EXPECT_GE(assets::psnr(by_hand, moved), kMinimumPsnr) << mode;
    EXPECT_LT(assets::psnr(before, moved), 35.0) << mode << ": the lights moved visibly";
  }
}

TEST_F(LightAnimationOnGpu, EveryModeDrawsTheMovedLightsAsLightsPlacedThereByHand) {
  std::vector<std::string> modes = testing::non_forward_modes();
  modes.insert(modes.begin(), "forward");
  expect_moved_as_placed(modes, 0);
}

// The shadowed lights' maps are drawn on the CPU's side: from where the GPU
// places the light this frame, not from its origin.
TEST_F(LightAnimationOnGpu, ShadowedMovingLightsCastFromWhereTheyAre) {
  expect_moved_as_placed({"forward", "clustered-deferred", "visibility-buffer"}, 12);
}

// Without compute shaders (WebGL2, OpenGL 4.1, ES 3.0) the CPU moves every
// light, as before: their Transforms are where the animation puts them.
TEST_F(LightAnimationOnGpu, OnTheComputeFreeTierTheCpuMovesThem) {
  WorldOptions options = options_for("forward");
  options.technique_options.compute_free = true;
  World world(options);
  animate_point_lights(world);
  EXPECT_FALSE(world.registry().resource<LightAnimationSettings>().on_gpu);
  run_animated(world);
  ecs::Registry& registry = world.registry();
  for (const ecs::Entity e : std::vector<ecs::Entity>(registry.entities_with<LightAnimation>().begin(), registry.entities_with<LightAnimation>().end())) {
    EXPECT_EQ(registry.get<Transform>(e).position, animated_position(registry.get<LightAnimation>(e), kStep * kFrames));
  }
  const assets::Image moved = world.renderer().read_output();
  World placed(options);
  animate_point_lights(placed);
  place_by_hand(placed);
  EXPECT_GE(assets::psnr(placed.renderer().read_output(), moved), kMinimumPsnr);
}

}  // namespace
}  // namespace atrium
