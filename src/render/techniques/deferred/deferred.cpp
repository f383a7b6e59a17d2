#include "render/techniques/deferred/deferred.hpp"

#include "render/frame/scene_passes.hpp"

namespace atrium::lighting {

DeferredTechnique::DeferredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius)
    : geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      lighting_(gpu.shaders(), {"post/fullscreen.vert", "deferred/lighting.frag"},
                cull_by_radius ? std::vector<gfx::ShaderDefine>{{"LIGHT_RADIUS_CULL"}} : std::vector<gfx::ShaderDefine>{},
                options.msaa),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void DeferredTechnique::add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) {
  add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  graph.add_pass("lighting", [&](render::PassBuilder& pass) {
    gbuffer_.read_targets(pass);
    pass.read(frame.light_buffer, render::Access::Storage);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [this, &targets](const render::PassResources& res) { gbuffer_.draw_fullscreen(res, lighting_, targets); });
  add_transparency_pass(graph, forward_, frame, targets);
}

}  // namespace atrium::lighting
