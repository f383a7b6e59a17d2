#include "systems/lighting/deferred.hpp"

namespace atrium::lighting {

DeferredTechnique::DeferredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius)
    : geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      lighting_(gpu.shaders(), {"post/fullscreen.vert", "deferred/lighting.frag"},
                cull_by_radius ? std::vector<gfx::ShaderDefine>{{"LIGHT_RADIUS_CULL"}} : std::vector<gfx::ShaderDefine>{},
                options.msaa),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void DeferredTechnique::resize(const FrameTargets& targets) { gbuffer_.resize(targets.size, targets.depth_stencil); }

void DeferredTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  gbuffer_.draw_geometry(geometry_, frame);
  {
    const auto pass = frame.timer.scope("lighting");
    gbuffer_.draw_fullscreen(lighting_, targets);
  }

  draw_transparent(forward_, frame, targets);
}

}  // namespace atrium::lighting
