// Forward shading (mode `forward`): reads the draw list and every light; writes
// the HDR colour and depth targets in one geometry pass, opaque first, then
// blended geometry back to front. The reference baseline: no pre-pass, no culling
// of lights, so its cost is fragments drawn x lights.
#pragma once

#include "gfx/shader_program.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class ForwardTechnique final : public LightingTechnique {
 public:
  ForwardTechnique(render::GpuAssets& gpu, const TechniqueOptions& options);
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

 private:
  gfx::ShaderProgram& program_;
};

}  // namespace atrium::techniques
