// The window's systems without a window: each test builds a registry, feeds
// the InputState or clock a system reads, runs one frame and checks components.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/epsilon.hpp>

#include "base/golden_angle.hpp"
#include "components/bounds.hpp"
#include "components/camera.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "systems/camera.hpp"
#include "systems/fly_camera.hpp"
#include "systems/input.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

TEST(InputSystem, TurnsEventsIntoPressesHeldKeysAndMouseMotion) {
  InputState state;
  const std::vector<InputEvent> frame1{
      {InputEvent::Kind::Key, GLFW_KEY_T, GLFW_PRESS, GLFW_MOD_SHIFT, {}},
      {InputEvent::Kind::Key, GLFW_KEY_T, GLFW_RELEASE, 0, {}},
      {InputEvent::Kind::Key, GLFW_KEY_W, GLFW_PRESS, 0, {}},
      {InputEvent::Kind::Key, GLFW_KEY_W, GLFW_REPEAT, 0, {}},
      {InputEvent::Kind::Key, GLFW_KEY_UNKNOWN, GLFW_PRESS, 0, {}},
      {InputEvent::Kind::MouseButton, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0, {}},
      {InputEvent::Kind::Cursor, 0, 0, 0, {10.0, 20.0}},
      {InputEvent::Kind::Cursor, 0, 0, 0, {14.0, 17.0}},
      {InputEvent::Kind::Scroll, 0, 0, 0, {0.0, 2.0}},
  };
  apply_input_events(state, frame1, 0.0);
  ASSERT_EQ(state.pressed.size(), 2u) << "a repeat is not a press; unknown keys are dropped";
  EXPECT_EQ(state.pressed[0].key, GLFW_KEY_T);
  EXPECT_EQ(state.pressed[0].mods, GLFW_MOD_SHIFT);
  EXPECT_FALSE(state.held.test(GLFW_KEY_T));
  EXPECT_TRUE(state.held.test(GLFW_KEY_W));
  EXPECT_TRUE(state.looking);
  EXPECT_EQ(state.cursor_delta, glm::dvec2(14.0, 17.0));
  EXPECT_EQ(state.scroll, 2.0);

  apply_input_events(state, {}, 0.0);  // the next frame: nothing happened
  EXPECT_TRUE(state.pressed.empty());
  EXPECT_TRUE(state.held.test(GLFW_KEY_W)) << "held until released";
  EXPECT_EQ(state.cursor_delta, glm::dvec2(0.0));
  EXPECT_EQ(state.scroll, 0.0);
}

struct FlyRig {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  ecs::Entity camera;
  FlyRig() {
    registry.set_resource<InputState>();
    camera = registry.create();
    registry.add<Transform>(camera);
    registry.add<Camera>(camera);
    registry.add<CameraAngles>(camera);
    registry.add<FlyCamera>(camera, FlyCamera{2.0f});
    register_fly_camera(scheduler);
  }
  InputState& input() { return registry.resource<InputState>(); }
  Transform& transform() { return registry.get<Transform>(camera); }
  CameraAngles& angles() { return registry.get<CameraAngles>(camera); }
  // `key` down for `seconds` of the coming frame.
  void hold(int key, double seconds) {
    input().held.set(static_cast<std::size_t>(key));
    input().down_seconds[static_cast<std::size_t>(key)] = seconds;
  }
};

// Key events carry their own times: at 0.5 fps a tap between two frames acts
// once and moves the camera for as long as it lasted, and a hold that spans a
// frame counts on each side of it for its own part.
TEST(InputSystem, TapsAndHoldsBetweenSlowFramesCountForTheirOwnLength) {
  FlyRig rig;
  InputState& input = rig.input();
  apply_input_events(input, {}, 10.0);
  const std::vector<InputEvent> taps{
      {InputEvent::Kind::Key, GLFW_KEY_T, GLFW_PRESS, 0, {}, 10.4},
      {InputEvent::Kind::Key, GLFW_KEY_T, GLFW_RELEASE, 0, {}, 10.48},
      {InputEvent::Kind::Key, GLFW_KEY_W, GLFW_PRESS, 0, {}, 10.7},
      {InputEvent::Kind::Key, GLFW_KEY_W, GLFW_RELEASE, 0, {}, 10.78},
      {InputEvent::Kind::Key, GLFW_KEY_D, GLFW_PRESS, 0, {}, 11.5},
  };
  apply_input_events(input, taps, 12.0);
  ASSERT_EQ(input.pressed.size(), 3u);
  EXPECT_EQ(input.pressed[0].key, GLFW_KEY_T) << "a tap between frames is one press";
  EXPECT_NEAR(input.down(GLFW_KEY_W), 0.08, 1e-9);
  EXPECT_NEAR(input.down(GLFW_KEY_D), 0.5, 1e-9);
  EXPECT_FALSE(input.held.test(GLFW_KEY_W));
  rig.scheduler.run_frame(rig.registry, 2.0);
  // At 2 m/s, w (-Z) for 0.08 s and d (+X) for 0.5 s: towards (0.5, 0, -0.08),
  // as far as the longer key went (1 m), not for the frame's 2 s.
  const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, -0.08f)) * 1.0f;
  EXPECT_TRUE(glm::all(glm::epsilonEqual(rig.transform().position, expected, 1e-5f)));
  const glm::vec3 after_first = rig.transform().position;

  const std::vector<InputEvent> release{{InputEvent::Kind::Key, GLFW_KEY_D, GLFW_RELEASE, 0, {}, 12.3}};
  apply_input_events(input, release, 14.0);
  EXPECT_TRUE(input.pressed.empty());
  EXPECT_NEAR(input.down(GLFW_KEY_D), 0.3, 1e-9) << "from the frame's start to the release";
  rig.scheduler.run_frame(rig.registry, 2.0);
  EXPECT_NEAR(rig.transform().position.x - after_first.x, 0.6f, 1e-5f);
  apply_input_events(input, {}, 16.0);
  EXPECT_EQ(input.down(GLFW_KEY_D), 0.0);
}

TEST(FlyCameraSystem, WMovesForwardAlongTheViewAtItsSpeedAndShiftIsFaster) {
  FlyRig rig;
  rig.hold(GLFW_KEY_W, 0.5);
  rig.scheduler.run_frame(rig.registry, 0.5);
  EXPECT_TRUE(glm::all(glm::epsilonEqual(rig.transform().position, glm::vec3(0, 0, -1), 1e-5f)));  // yaw 0 looks along -Z
  rig.angles().yaw_degrees = 90.0f;  // now along +X
  rig.hold(GLFW_KEY_LEFT_SHIFT, 0.5);
  rig.scheduler.run_frame(rig.registry, 0.5);
  EXPECT_TRUE(glm::all(glm::epsilonEqual(rig.transform().position, glm::vec3(4, 0, -1), 1e-4f)));
}

TEST(FlyCameraSystem, QAndEMoveStraightDownAndUpWhateverThePitch) {
  FlyRig rig;
  rig.angles().pitch_degrees = 60.0f;
  rig.hold(GLFW_KEY_E, 1.0);
  rig.scheduler.run_frame(rig.registry, 1.0);
  EXPECT_TRUE(glm::all(glm::epsilonEqual(rig.transform().position, glm::vec3(0, 2, 0), 1e-5f)));
}

TEST(FlyCameraSystem, MouseDragAndArrowsTurnAndPitchStopsShortOfVertical) {
  FlyRig rig;
  rig.input().looking = true;
  rig.input().cursor_delta = {100.0, -2000.0};  // right, and far up
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_NEAR(rig.angles().yaw_degrees, 15.0f, 1e-4f);
  EXPECT_EQ(rig.angles().pitch_degrees, kMaxPitchDegrees);
  rig.input().looking = false;
  rig.hold(GLFW_KEY_LEFT, 0.5);
  rig.scheduler.run_frame(rig.registry, 0.5);
  EXPECT_NEAR(rig.angles().yaw_degrees, 15.0f - 45.0f, 1e-4f);
  const glm::quat expected = camera_rotation(rig.angles().yaw_degrees, rig.angles().pitch_degrees);
  EXPECT_NEAR(glm::abs(glm::dot(rig.transform().rotation, expected)), 1.0f, 1e-5f) << "the Transform follows the angles";
}

TEST(FlyCameraSystem, ScrollScalesTheSpeedWithinLimitsAndTheOverlayKeepsItsEvents) {
  FlyRig rig;
  rig.input().scroll = 2.0;
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_NEAR(rig.registry.get<FlyCamera>(rig.camera).speed, 2.0f * 1.5625f, 1e-5f);
  rig.input().scroll = -1000.0;
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_EQ(rig.registry.get<FlyCamera>(rig.camera).speed, kMinFlySpeed);
  // While the overlay has the keyboard, w does not move the camera.
  rig.input().scroll = 0.0;
  rig.input().ui_wants_keyboard = true;
  rig.hold(GLFW_KEY_W, 1.0);
  rig.scheduler.run_frame(rig.registry, 1.0);
  EXPECT_EQ(rig.transform().position, glm::vec3(0.0f));
}

// A stored view moves the camera as a cut, which the frame's ViewState says
// for that frame only; flying, however far, is not one.
TEST(CameraSystem, AStoredViewIsACutForOneFrameAndFlyingIsNot) {
  FlyRig rig;
  rig.registry.set_resource<Viewport>();
  const ViewState& view = rig.registry.set_resource<ViewState>();
  register_camera(rig.scheduler);
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_FALSE(view.cut);
  apply_view(rig.registry, assets::NamedView{"court", glm::vec3(5.0f, 1.0f, -2.0f), 90.0f, 0.0f});
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_TRUE(view.cut);
  EXPECT_EQ(view.camera_position, glm::vec3(5.0f, 1.0f, -2.0f));
  EXPECT_FALSE(rig.registry.has<CameraCut>(rig.camera)) << "taken off once the frame has it";
  rig.scheduler.run_frame(rig.registry, 0.0);
  EXPECT_FALSE(view.cut);
  rig.hold(GLFW_KEY_W, 10.0);
  rig.scheduler.run_frame(rig.registry, 10.0);
  EXPECT_GT(glm::length(view.camera_position - glm::vec3(5.0f, 1.0f, -2.0f)), 10.0f);
  EXPECT_FALSE(view.cut);
}

// After a cut the near and far planes are those of a camera that starts
// there, whatever view came before: a small step keeps the last planes (so
// that clusters hold still while flying), a stored view does not.
TEST(CameraSystem, AStoredViewsDepthPlanesDoNotDependOnTheViewBefore) {
  const auto planes_at = [](const std::vector<glm::vec3>& path, bool cut_each) {
    FlyRig rig;
    rig.registry.set_resource<Viewport>();
    rig.registry.set_resource<SceneBounds>(SceneBounds{{glm::vec3(-10.0f), glm::vec3(10.0f), false}});
    const ViewState& view = rig.registry.set_resource<ViewState>();
    register_camera(rig.scheduler);
    for (std::size_t i = 0; i < path.size(); ++i) {
      if (i == 0 || cut_each) {
        apply_view(rig.registry, assets::NamedView{"v", path[i], 0.0f, 0.0f});
      } else {
        rig.transform().position = path[i];
      }
      rig.scheduler.run_frame(rig.registry, 0.0);
    }
    return glm::vec2(view.near_plane, view.far_plane);
  };
  const glm::vec3 there(0.0f, 0.0f, 29.0f), before(0.0f, 0.0f, 30.0f);
  const glm::vec2 fresh = planes_at({there}, true);
  EXPECT_EQ(planes_at({before, there}, true), fresh) << "a cut from a view a metre behind";
  EXPECT_NE(planes_at({before, there}, false), fresh) << "flying that metre keeps the planes it had";
}

// A light moves radius * speed / 60 along its circle in a frame of 60 Hz: so
// must the millionth generated light, an hour in too. A float phase of a
// million golden angles is 0.25 rad coarse, and such lights jumped.
TEST(LightAnimationSystem, TheMillionthLightStillMovesEveryFrame) {
  for (const std::uint64_t k : {std::uint64_t{0}, std::uint64_t{1000}, std::uint64_t{1} << 20}) {
    const float phase = golden_angle_phase(k);
    EXPECT_GE(phase, 0.0f);
    EXPECT_LT(phase, glm::two_pi<float>());
    const long double exact = static_cast<long double>(kGoldenAngle) * static_cast<long double>(k);
    EXPECT_NEAR(std::cos(phase), static_cast<float>(std::cos(exact)), 1e-5f) << k;
    const LightAnimation animation{glm::vec3(0.0f), phase, 0.5f, 0.6f};
    for (const double time : {0.0, 3600.0}) {
      const float step = glm::distance(animated_position(animation, time), animated_position(animation, time + 1.0 / 60.0));
      EXPECT_NEAR(step, 0.5f * 0.6f / 60.0f, 0.0015f) << "light " << k << " at " << time << " s";
    }
  }
}

// Many lights are split over threads: every one is moved, each to its own place.
TEST(LightAnimationSystem, EveryOneOfManyLightsIsMovedToItsOwnPlace) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  registry.set_resource<LightAnimationSettings>();
  register_light_animation(scheduler, registry);
  std::vector<ecs::Entity> lights;
  for (std::uint64_t k = 0; k < 40'000; ++k) {
    const ecs::Entity e = registry.create();
    const glm::vec3 origin(static_cast<float>(k % 200), 1.0f, static_cast<float>(k / 200));
    // Every tenth light got its animation before its Transform: another pool order.
    if (k % 10 == 0) registry.add<LightAnimation>(e, origin, golden_angle_phase(k));
    registry.add<Transform>(e, Transform{origin});
    if (k % 10 != 0) registry.add<LightAnimation>(e, origin, golden_angle_phase(k));
    lights.push_back(e);
  }
  scheduler.run_frame(registry, 0.5);
  const double time = registry.resource<LightAnimationSettings>().time;
  for (const ecs::Entity e : lights) {
    ASSERT_EQ(registry.get<Transform>(e).position, animated_position(registry.get<LightAnimation>(e), time)) << e.index;
  }
}

// A light at `at` on a circle of 0.5 m through it, 1 rad/s.
ecs::Entity add_animated_light(ecs::Registry& registry, glm::vec3 at) {
  const ecs::Entity e = registry.create();
  registry.add<Transform>(e, Transform{at});
  registry.add<LightAnimation>(e, at, 0.7f, 0.5f, 1.0f);
  return e;
}

// Where point lights move on the GPU, the system moves only the lights the
// GPU does not: spot and directional lights (their records have no room for a motion).
TEST(LightAnimationSystem, OnTheGpuTierMovesOnlySpotAndDirectionalLights) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  registry.set_resource<LightAnimationSettings>().on_gpu = true;
  register_light_animation(scheduler, registry);
  const ecs::Entity point = add_animated_light(registry, glm::vec3(1, 2, 3));
  const ecs::Entity spot = add_animated_light(registry, glm::vec3(4, 2, 3));
  registry.add<SpotCone>(spot);
  const ecs::Entity sun = add_animated_light(registry, glm::vec3(7, 2, 3));
  registry.add<DirectionalLight>(sun);
  scheduler.run_frame(registry, 0.5);
  EXPECT_EQ(registry.get<Transform>(point).position, glm::vec3(1, 2, 3)) << "the GPU places it";
  for (const ecs::Entity e : {spot, sun}) {
    EXPECT_EQ(registry.get<Transform>(e).position, animated_position(registry.get<LightAnimation>(e), 0.5));
  }
  EXPECT_TRUE(moves_on_gpu(registry.resource<LightAnimationSettings>(), false, false));
  EXPECT_FALSE(moves_on_gpu(registry.resource<LightAnimationSettings>(), true, false));
  EXPECT_FALSE(moves_on_gpu(registry.resource<LightAnimationSettings>(), false, true));
  EXPECT_FALSE(moves_on_gpu(LightAnimationSettings{}, false, false)) << "off the GPU tier every light moves on the CPU";
}

// animated_reach bounds how far a light strays from its origin at any time,
// and no more loosely than it must: some phase and time come within a
// thousandth of it (half a turn on, across the circle).
TEST(LightAnimationSystem, AnimatedLightsStayWithinTheirReach) {
  for (const float radius : {0.5f, 2.0f, -1.0f}) {
    float farthest = 0.0f;
    for (int p = 0; p < 64; ++p) {
      const LightAnimation animation{glm::vec3(1, 2, 3), static_cast<float>(p) * 0.1f, radius, 0.6f};
      for (int t = 0; t < 400; ++t) {
        farthest = std::max(farthest, glm::distance(animated_position(animation, t * 0.05), animation.origin));
      }
    }
    EXPECT_LE(farthest, animated_reach({glm::vec3(0.0f), 0.0f, radius, 0.6f}) * (1.0f + 1e-5f)) << radius;
    EXPECT_GE(farthest, animated_reach({glm::vec3(0.0f), 0.0f, radius, 0.6f}) * 0.999f) << radius;
  }
}

TEST(LightAnimationSystem, MovesAnimatedLightsFromWhereTheyStartedAndPauses) {
  ecs::Registry registry;
  ecs::Scheduler scheduler;
  registry.set_resource<LightAnimationSettings>();
  register_light_animation(scheduler, registry);
  const ecs::Entity moving = add_animated_light(registry, glm::vec3(1, 2, 3));
  const ecs::Entity placed = registry.create();
  registry.add<Transform>(placed, Transform{glm::vec3(5, 5, 5)});

  EXPECT_EQ(animated_position(registry.get<LightAnimation>(moving), 0.0), glm::vec3(1, 2, 3)) << "starts at its origin";
  scheduler.run_frame(registry, 0.25);
  const glm::vec3 after = registry.get<Transform>(moving).position;
  EXPECT_GT(glm::distance(after, glm::vec3(1, 2, 3)), 0.05f);
  EXPECT_LE(glm::distance(glm::vec2(after.x, after.z), glm::vec2(1, 3)), 2.0f * 0.5f + 1e-5f) << "stays on its circle";
  EXPECT_EQ(registry.get<Transform>(placed).position, glm::vec3(5, 5, 5)) << "lights without LightAnimation stay put";

  registry.resource<LightAnimationSettings>().paused = true;
  scheduler.run_frame(registry, 1.0);
  EXPECT_EQ(registry.get<Transform>(moving).position, after);
  registry.resource<LightAnimationSettings>().paused = false;
  scheduler.run_frame(registry, 2.0 * 3.14159265 - 0.25);  // a full turn at 1 rad/s
  EXPECT_LT(glm::distance(registry.get<Transform>(moving).position, glm::vec3(1, 2, 3)), 1e-4f) << "a circle comes back";
}

}  // namespace
}  // namespace atrium
