// Test parameters drawn from the technique table, so that a new mode or
// G-buffer layout is covered by every comparison without editing the tests.
#pragma once

#include <string>
#include <tuple>
#include <vector>

#include "render/techniques/technique.hpp"
#include "components/technique_options.hpp"

namespace atrium::testing {

// The modes that run with `options` (techniques::refusal: a tier without
// compute shaders, MSAA) but forward, in table order.
inline std::vector<std::string> non_forward_modes(const TechniqueOptions& options = {}) {
  std::vector<std::string> modes = techniques::mode_names(options);
  std::erase(modes, "forward");
  return modes;
}

inline std::vector<GBufferLayout> gbuffer_layouts() {
  return {GBufferLayout::Full, GBufferLayout::Compact};
}

// Each non-forward mode with every --gbuffer layout where the layout changes
// its G-buffer (GBufferUse::Chosen), and once elsewhere: a second run of a mode
// the layout does not touch would only repeat the first.
// Only the modes that run with `options` (techniques::refusal).
inline std::vector<std::tuple<std::string, GBufferLayout>> mode_layouts(const TechniqueOptions& options = {}) {
  std::vector<std::tuple<std::string, GBufferLayout>> pairs;
  for (const techniques::TechniqueInfo& info : techniques::technique_table()) {
    if (info.name == "forward" || !techniques::refusal(info, options).empty()) continue;
    if (info.gbuffer != techniques::GBufferUse::Chosen) {
      pairs.emplace_back(std::string(info.name), GBufferLayout::Full);
      continue;
    }
    for (const GBufferLayout layout : gbuffer_layouts()) pairs.emplace_back(std::string(info.name), layout);
  }
  return pairs;
}

inline TechniqueOptions with_layout(GBufferLayout layout) {
  TechniqueOptions options;
  options.gbuffer_layout = layout;
  return options;
}

// A gtest-safe name: "clustered-deferred", Compact -> "clustered_deferred_compact".
inline std::string test_name(std::string mode, GBufferLayout layout) {
  mode += '_';
  mode += kGBufferLayoutNames[static_cast<std::size_t>(layout)];
  for (char& c : mode) if (c == '-') c = '_';
  return mode;
}

}  // namespace atrium::testing
