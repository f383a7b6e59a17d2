// The "present" module (window stage, first): copies the 8-bit output
// (FrameBuild::output) to the window's framebuffer when the frame is shown in
// a window (RendererSettings::present_to_window); the window's modules (the
// overlay) then draw over it.
#pragma once

#include "render/frame/frame_modules.hpp"

namespace atrium::render {

[[nodiscard]] FrameModule present_module();

}  // namespace atrium::render
