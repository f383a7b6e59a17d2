// Fixed phases in a fixed order; within a phase, systems run in the order they
// were registered. A system is any callable over the registry.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/registry.hpp"

namespace atrium::ecs {

enum class Phase { Input, Update, PostUpdate, Render };
inline constexpr std::array kPhases{Phase::Input, Phase::Update, Phase::PostUpdate, Phase::Render};

[[nodiscard]] std::string_view phase_name(Phase phase);

// The frame clock, kept as a registry resource and advanced by Scheduler::run_frame.
struct FrameClock {
  double delta_seconds = 0.0;
  double elapsed_seconds = 0.0;
  std::uint64_t frame = 0;
};

using System = std::function<void(Registry&)>;

// How long one system ran on the CPU in the last frame: what lies between a
// frame's wall-clock time and its passes' GPU time (the bench reports it).
struct SystemTime {
  std::string name;  // "Phase/name"
  double milliseconds = 0.0;
};

class Scheduler {
 public:
  void add(Phase phase, std::string name, System system);

  // Advances the FrameClock by delta_seconds, then runs every phase in order.
  void run_frame(Registry& registry, double delta_seconds);
  void run_phase(Phase phase, Registry& registry);

  // "Phase/name" of every system in execution order, for tests and the docs.
  [[nodiscard]] std::vector<std::string> execution_order() const;
  // Each system's time in the last run_frame, in execution order.
  [[nodiscard]] std::vector<SystemTime> last_frame_times() const;

 private:
  struct Entry {
    std::string name;
    System system;
    double milliseconds = 0.0;  // its last run
  };
  std::array<std::vector<Entry>, kPhases.size()> phases_;
};

}  // namespace atrium::ecs
