// The shading models users choose with --shading: the names, and the value of
// SHADING_MODEL that shaders/common/brdf.glsl is compiled with.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/shader_globals.hpp"

namespace atrium::lighting {

inline constexpr std::array<std::string_view, 3> kShadingModels{"pbr", "blinn-phong", "phong"};

// The SHADING_MODEL value of a name, or -1 when no model has that name.
[[nodiscard]] inline int shading_model_index(std::string_view name) {
  for (std::size_t i = 0; i < kShadingModels.size(); ++i) {
    if (kShadingModels[i] == name) return static_cast<int>(i);
  }
  return -1;
}

// The SHADING_MODEL row of the shader globals (render/shader_globals.hpp).
// Throws std::invalid_argument for a name no model has.
inline void shading_model_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
  const int model = shading_model_index(inputs.settings.shading);
  if (model < 0) throw std::invalid_argument("unknown shading model '" + inputs.settings.shading + "'");
  defines.push_back({"SHADING_MODEL", std::to_string(model)});
}

[[nodiscard]] inline std::string shading_model_names() {
  std::string names;
  for (const auto name : kShadingModels) names += (names.empty() ? "" : ", ") + std::string(name);
  return names;
}

}  // namespace atrium::lighting
