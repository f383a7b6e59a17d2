// Deferred shading (modes `deferred` and `deferred-radius`): a geometry pass
// writes the G-buffer, one full-screen pass (fragment or compute,
// --lighting-stage) reads it and loops over every light for every visible pixel, then blended geometry is drawn forward on top.
// `deferred-radius` compiles the lighting pass with LIGHT_RADIUS_CULL: a light
// is skipped where its radius does not reach, which cannot change the picture
// because the falloff is already zero there.
#pragma once

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::lighting {

class DeferredTechnique final : public LightingTechnique {
 public:
  DeferredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius);
  void add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) override;

 private:
  gfx::ShaderProgram& geometry_;
  LightingPass lighting_;
  gfx::ShaderProgram& forward_;
  GBuffer gbuffer_;
};

}  // namespace atrium::lighting
