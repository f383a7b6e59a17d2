// Deferred shading (modes `deferred` and `deferred-radius`): a geometry pass
// writes the G-buffer, one full-screen pass (fragment or compute,
// --lighting-stage) reads it and loops over every light for every visible pixel, then blended geometry is drawn forward on top.
// `deferred-radius` compiles the lighting pass with LIGHT_RADIUS_CULL: a light
// is skipped where its radius does not reach, which cannot change the picture
// because the falloff is already zero there. Many lights are summed in runs of
// lights_per_run(), each short on any GPU, the later ones adding to the first.
#pragma once

#include <optional>

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class DeferredTechnique final : public LightingTechnique {
 public:
  DeferredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius);
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

 private:
  // The lighting pass over every light, in runs of lights_per_run().
  void light(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);

  gfx::ShaderLibrary& shaders_;
  TechniqueOptions options_;
  bool cull_by_radius_;
  gfx::ShaderProgram& geometry_;
  lighting::LightingPass lighting_;
  std::optional<lighting::LightingPass> adding_;  // the runs after the first (ADD_LIGHTS), built when a frame first needs one
  gfx::ShaderProgram& forward_;
  lighting::GBuffer gbuffer_;
};

}  // namespace atrium::techniques
