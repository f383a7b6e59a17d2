// The defines every shader of a frame is compiled with. Each is declared by
// the part of the renderer that needs it, as a row that decides it from the
// frame's settings: the shading model (render/lighting/shading_model.hpp), the debug
// views' counters (render/debug/debug_views.hpp), the G-buffer layout
// (render/lighting/gbuffer.hpp), the light-sum targets and MSAA (the renderer's
// targets) and shadows (render/shadows/shadow_atlas.hpp). The renderer recompiles
// when the rows' defines change.
#pragma once

#include <vector>

#include "components/frame_resources.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::render {

struct GlobalDefineInputs {
  const RendererSettings& settings;
  bool count_lights;     // the shown debug view counts lights evaluated per pixel
  bool count_fragments;  // ... or fragments rasterised per pixel
  bool split_lighting;  // the diffuse and specular sums are written this frame
};

// Adds the defines the row's owner needs to `defines` (none is fine).
using GlobalDefineRow = void (*)(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines);

}  // namespace atrium::render
