// The "tonemap" module (output): reads the frame's colour image as the
// post-process stage left it (FrameBuild::color, linear HDR, multisampled with
// MSAA) and writes the 8-bit display image (FrameBuild::output): exposure, the
// filmic curve, sRGB, and with MSAA the resolve (shaders/common/tonemap.glsl).
// A full-screen fragment pass, or with the compute lighting stage a compute
// pass that stores each pixel with imageStore.
#pragma once

#include "gfx/shader_library.hpp"
#include "render/frame/draw_list.hpp"
#include "render/frame/frame_modules.hpp"

namespace atrium::render {

class TonemapPass {
 public:
  explicit TonemapPass(gfx::ShaderLibrary& shaders) : shaders_(shaders) {}
  [[nodiscard]] FrameModule module();

 private:
  gfx::ShaderLibrary& shaders_;
  // Fetched on first use after the module's hook (the global defines changed: MSAA_SAMPLES).
  gfx::ShaderProgram* fragment_ = nullptr;
  gfx::ShaderProgram* compute_ = nullptr;
  FullscreenTriangle triangle_;
};

}  // namespace atrium::render
