#include <gtest/gtest.h>

#include "ecs/scheduler.hpp"

#include <chrono>
#include <thread>

namespace atrium::ecs {
namespace {

struct Log {
  std::vector<std::string> calls;
};

TEST(Scheduler, RunsPhasesInFixedOrderAndSystemsInRegistrationOrder) {
  Registry registry;
  registry.set_resource<Log>();
  Scheduler scheduler;
  auto record = [](std::string name) { return [name](Registry& r) { r.resource<Log>().calls.push_back(name); }; };
  // Registered out of phase order on purpose.
  scheduler.add(Phase::Render, "draw", record("draw"));
  scheduler.add(Phase::Update, "move", record("move"));
  scheduler.add(Phase::Input, "keys", record("keys"));
  scheduler.add(Phase::Update, "animate", record("animate"));
  scheduler.add(Phase::PostUpdate, "camera", record("camera"));
  scheduler.add(Phase::Input, "mouse", record("mouse"));
  scheduler.run_frame(registry, 0.016);
  EXPECT_EQ(registry.resource<Log>().calls,
            (std::vector<std::string>{"keys", "mouse", "move", "animate", "camera", "draw"}));
  EXPECT_EQ(scheduler.execution_order(),
            (std::vector<std::string>{"Input/keys", "Input/mouse", "Update/move", "Update/animate", "PostUpdate/camera",
                                      "Render/draw"}));
}

TEST(Scheduler, FrameClockAdvancesEachFrame) {
  Registry registry;
  Scheduler scheduler;
  double seen_delta = -1.0;
  std::uint64_t seen_frame = 99;
  scheduler.add(Phase::Update, "probe", [&](Registry& r) {
    seen_delta = r.resource<FrameClock>().delta_seconds;
    seen_frame = r.resource<FrameClock>().frame;
  });
  scheduler.run_frame(registry, 0.5);
  EXPECT_DOUBLE_EQ(seen_delta, 0.5);
  EXPECT_EQ(seen_frame, 0u);
  scheduler.run_frame(registry, 0.25);
  EXPECT_EQ(seen_frame, 1u);
  EXPECT_DOUBLE_EQ(registry.resource<FrameClock>().elapsed_seconds, 0.75);
  EXPECT_EQ(registry.resource<FrameClock>().frame, 2u);
}

TEST(Scheduler, RunPhaseRunsOnlyThatPhase) {
  Registry registry;
  Scheduler scheduler;
  int input = 0, render = 0;
  scheduler.add(Phase::Input, "i", [&](Registry&) { ++input; });
  scheduler.add(Phase::Render, "r", [&](Registry&) { ++render; });
  scheduler.run_phase(Phase::Render, registry);
  EXPECT_EQ(input, 0);
  EXPECT_EQ(render, 1);
}

TEST(Scheduler, TimesEachSystemOfTheLastFrame) {
  Registry registry;
  Scheduler scheduler;
  scheduler.add(Phase::Render, "slow", [](Registry&) { std::this_thread::sleep_for(std::chrono::milliseconds(20)); });
  scheduler.add(Phase::Update, "quick", [](Registry&) {});
  scheduler.run_frame(registry, 0.016);
  const std::vector<SystemTime> times = scheduler.last_frame_times();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0].name, "Update/quick");
  EXPECT_EQ(times[1].name, "Render/slow");
  EXPECT_GE(times[1].milliseconds, 20.0);
  EXPECT_LT(times[0].milliseconds, times[1].milliseconds);
}

}  // namespace
}  // namespace atrium::ecs
