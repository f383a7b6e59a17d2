// Numeric settings of optional systems, by the system's name: the command line
// (a row of app/command_line.cpp's system options), a scene file's "systems"
// object and the overlay set them; each system declares its own (label and
// range, for the overlay's slider) and reads it every frame. Plain data.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <string_view>

namespace atrium {

struct SystemOption {
  // What the overlay's slider steps by: whole numbers (a count) or any value.
  enum class Step { Whole, Fraction };
  double value = 0.0;
  // Set by the system that reads it (declare); an undeclared option is shown
  // nowhere and read by no one.
  std::string label;
  double min = 0.0, max = 0.0;
  Step step = Step::Whole;
  bool declared = false;
};

struct SystemOptions {
  std::map<std::string, SystemOption, std::less<>> options;

  // The value set for `name`, or `fallback` when none was.
  [[nodiscard]] double value(std::string_view name, double fallback = 0.0) const {
    const auto it = options.find(name);
    return it == options.end() ? fallback : it->second.value;
  }
  void set(const std::string& name, double value) { options[name].value = value; }
  // A system names its option: the overlay shows it as a slider over
  // [min, max]; a value set before (command line, scene file) is kept,
  // clamped, and one never set starts at `initial`.
  void declare(const std::string& name, std::string label, double min, double max, SystemOption::Step step = SystemOption::Step::Whole,
               double initial = 0.0) {
    const bool was_set = options.count(name) != 0;
    SystemOption& option = options[name];
    option.label = std::move(label);
    option.min = min;
    option.max = max;
    option.step = step;
    option.value = std::clamp(was_set ? option.value : initial, min, max);
    option.declared = true;
  }
};

}  // namespace atrium
