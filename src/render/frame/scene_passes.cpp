#include "render/frame/scene_passes.hpp"

#include "gfx/depth.hpp"
#include "render/frame/frame_draws.hpp"

namespace atrium::render {

void add_geometry_pass(FrameGraph& graph, lighting::GBuffer& gbuffer, gfx::ShaderProgram& program, const FrameContext& frame,
                       const FrameTargets& targets) {
  graph.add_pass("geometry", [&](PassBuilder& pass) {
    read_draws(pass, frame);
    gbuffer.create_targets(pass, targets.size, frame.scene_depth);
  },
                 [&gbuffer, &program, &frame](const PassResources& res) { gbuffer.draw_geometry(res, program, frame); });
}

void add_transparency_pass(FrameGraph& graph, gfx::ShaderProgram& program, const FrameContext& frame, const FrameTargets& targets,
                           const std::function<void(PassBuilder&)>& reads, std::function<void()> prepare) {
  if (frame.draws.list().blended.empty()) return;
  graph.add_pass("transparency", [&](PassBuilder& pass) {
    pass.read(frame.scene_depth, Access::Attachment);
    read_shading_inputs(pass, frame);
    read_draws(pass, frame);
    if (reads) reads(pass);
    pass.write(frame.scene_color, Access::Attachment);
  }, [&program, &frame, &targets, prepare = std::move(prepare)](const PassResources& res) {
    if (prepare) prepare();
    draw_transparent(res, program, frame, targets);
  });
}

}  // namespace atrium::render
