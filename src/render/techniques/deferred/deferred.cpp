#include "render/techniques/deferred/deferred.hpp"

#include "render/frame/scene_passes.hpp"

namespace atrium::lighting {

DeferredTechnique::DeferredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius)
    : geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      lighting_(gpu.shaders(), "deferred/lighting",
                cull_by_radius ? std::vector<gfx::ShaderDefine>{{"LIGHT_RADIUS_CULL"}} : std::vector<gfx::ShaderDefine>{}, options),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void DeferredTechnique::add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) {
  add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  graph.add_pass("lighting", [&](render::PassBuilder& pass) {
    lighting_.declare(pass, gbuffer_, frame);
    pass.read(frame.light_buffer, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) { lighting_.run(res, gbuffer_, frame, targets); });
  add_transparency_pass(graph, forward_, frame, targets);
}

}  // namespace atrium::lighting
