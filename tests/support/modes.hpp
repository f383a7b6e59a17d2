// Test parameters drawn from the technique table, so that a new mode or
// G-buffer layout is covered by every comparison without editing the tests.
#pragma once

#include <string>
#include <tuple>
#include <vector>

#include "render/techniques/technique.hpp"
#include "components/technique_options.hpp"

namespace atrium::testing {

inline std::vector<std::string> non_forward_modes() {
  std::vector<std::string> modes = lighting::mode_names();
  std::erase(modes, "forward");
  return modes;
}

inline std::vector<lighting::GBufferLayout> gbuffer_layouts() {
  return {lighting::GBufferLayout::Full, lighting::GBufferLayout::Compact};
}

// Each non-forward mode with every --gbuffer layout where the layout changes
// its G-buffer (GBufferUse::Chosen), and once elsewhere: a second run of a mode
// the layout does not touch would only repeat the first.
inline std::vector<std::tuple<std::string, lighting::GBufferLayout>> mode_layouts() {
  std::vector<std::tuple<std::string, lighting::GBufferLayout>> pairs;
  for (const lighting::TechniqueInfo& info : lighting::technique_table()) {
    if (info.name == "forward") continue;
    if (info.gbuffer != lighting::GBufferUse::Chosen) {
      pairs.emplace_back(std::string(info.name), lighting::GBufferLayout::Full);
      continue;
    }
    for (const lighting::GBufferLayout layout : gbuffer_layouts()) pairs.emplace_back(std::string(info.name), layout);
  }
  return pairs;
}

inline lighting::TechniqueOptions with_layout(lighting::GBufferLayout layout) {
  lighting::TechniqueOptions options;
  options.gbuffer_layout = layout;
  return options;
}

// A gtest-safe name: "clustered-deferred", Compact -> "clustered_deferred_compact".
inline std::string test_name(std::string mode, lighting::GBufferLayout layout) {
  mode += "_" + std::string(lighting::kGBufferLayoutNames[static_cast<std::size_t>(layout)]);
  for (char& c : mode) if (c == '-') c = '_';
  return mode;
}

}  // namespace atrium::testing
