#include "render/frame/scene_passes.hpp"

#include "gfx/depth.hpp"

namespace atrium::lighting {

void add_geometry_pass(render::FrameGraph& graph, GBuffer& gbuffer, gfx::ShaderProgram& program, const FrameContext& frame,
                       const FrameTargets& targets) {
  graph.add_pass("geometry", [&](render::PassBuilder& pass) { gbuffer.create_targets(pass, targets.size, frame.scene_depth); },
                 [&gbuffer, &program, &frame](const render::PassResources& res) { gbuffer.draw_geometry(res, program, frame); });
}

void add_transparency_pass(render::FrameGraph& graph, gfx::ShaderProgram& program, const FrameContext& frame, const FrameTargets& targets,
                           const std::function<void(render::PassBuilder&)>& reads, std::function<void()> prepare) {
  if (frame.draws.blended.empty()) return;
  graph.add_pass("transparency", [&](render::PassBuilder& pass) {
    pass.read(frame.scene_depth, render::Access::Attachment);
    read_shading_inputs(pass, frame);
    if (reads) reads(pass);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [&program, &frame, &targets, prepare = std::move(prepare)](const render::PassResources& res) {
    if (prepare) prepare();
    draw_transparent(res, program, frame, targets);
  });
}

}  // namespace atrium::lighting
