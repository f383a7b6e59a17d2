#include "ecs/scheduler.hpp"

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
  for (auto& entry : phases_[static_cast<std::size_t>(phase)]) entry.system(registry);
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

}  // namespace atrium::ecs
