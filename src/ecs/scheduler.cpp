#include "ecs/scheduler.hpp"

#include <chrono>

namespace atrium::ecs {

std::string_view phase_name(Phase phase) {
  switch (phase) {
    case Phase::Input: return "Input";
    case Phase::Update: return "Update";
    case Phase::PostUpdate: return "PostUpdate";
    case Phase::Render: return "Render";
  }
  return "?";
}

void Scheduler::add(Phase phase, std::string name, System system) {
  phases_[static_cast<std::size_t>(phase)].push_back({std::move(name), std::move(system)});
}

void Scheduler::run_frame(Registry& registry, double delta_seconds) {
  FrameClock* clock = registry.try_resource<FrameClock>();
  if (!clock) clock = &registry.set_resource<FrameClock>();
  clock->delta_seconds = delta_seconds;
  clock->elapsed_seconds += delta_seconds;
  for (Phase phase : kPhases) run_phase(phase, registry);
  ++clock->frame;
}

void Scheduler::run_phase(Phase phase, Registry& registry) {
  using Clock = std::chrono::steady_clock;
  for (auto& entry : phases_[static_cast<std::size_t>(phase)]) {
    const Clock::time_point start = Clock::now();
    entry.system(registry);
    entry.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
}

std::vector<std::string> Scheduler::execution_order() const {
  std::vector<std::string> order;
  for (Phase phase : kPhases) {
    for (const auto& entry : phases_[static_cast<std::size_t>(phase)]) {
      order.push_back(std::string(phase_name(phase)) + "/" + entry.name);
    }
  }
  return order;
}

std::vector<SystemTime> Scheduler::last_frame_times() const {
  std::vector<SystemTime> times;
  for (Phase phase : kPhases) {
    for (const auto& entry : phases_[static_cast<std::size_t>(phase)]) {
      times.push_back({std::string(phase_name(phase)) + "/" + entry.name, entry.milliseconds});
    }
  }
  return times;
}

}  // namespace atrium::ecs
