// The "clear light sums" module (before lighting): with the split on
// (TechniqueOptions::split_lighting, or a view of the sums), zeroes the
// diffuse and specular light sums that deferred lighting passes add to, so a
// forward mode, which leaves them untouched, shows no light rather than a
// stale frame. Writes FrameContext::diffuse_light and specular_light.
#pragma once

#include "render/frame/frame_modules.hpp"

namespace atrium::lighting {

[[nodiscard]] render::FrameModule light_sums_module();

}  // namespace atrium::lighting
