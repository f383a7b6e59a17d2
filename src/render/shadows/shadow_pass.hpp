// The "shadows" module (before lighting): draws the shadow maps that
// ShadowAtlas::update found stale into the atlas (the graph's "shadow-atlas",
// which every shading pass declares it reads through FrameContext::shadow_atlas),
// then binds the frame's draws again. Reused maps cost nothing: no pass.
#pragma once

#include "render/frame/frame_draws.hpp"
#include "render/frame/frame_modules.hpp"
#include "render/shadows/shadow_atlas.hpp"

namespace atrium::shadows {

[[nodiscard]] render::FrameModule shadow_module(ShadowAtlas& atlas, render::FrameDraws& draws);

}  // namespace atrium::shadows
