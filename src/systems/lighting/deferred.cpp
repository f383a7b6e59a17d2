#include "systems/lighting/deferred.hpp"

#include "systems/lighting/scene_passes.hpp"

namespace atrium::lighting {

DeferredTechnique::DeferredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius)
    : geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      lighting_(gpu.shaders(), {"post/fullscreen.vert", "deferred/lighting.frag"},
                cull_by_radius ? std::vector<gfx::ShaderDefine>{{"LIGHT_RADIUS_CULL"}} : std::vector<gfx::ShaderDefine>{},
                options.msaa),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void DeferredTechnique::resize(const FrameTargets& targets) { gbuffer_.resize(targets.size, targets.depth_stencil); }

void DeferredTechnique::add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) {
  const std::vector<render::ResourceId> gbuffer = add_geometry_pass(graph, gbuffer_, geometry_, frame);
  graph.add_pass("lighting", [&](render::PassBuilder& pass) {
    read_gbuffer(pass, gbuffer);
    pass.read(frame.light_buffer, render::Access::Storage);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [this, &targets](const render::PassResources&) { gbuffer_.draw_fullscreen(lighting_, targets); });
  add_transparency_pass(graph, forward_, frame, targets);
}

}  // namespace atrium::lighting
