#include "render/techniques/forward/forward.hpp"

#include "render/frame/scene_passes.hpp"

namespace atrium::techniques {

ForwardTechnique::ForwardTechnique(render::GpuAssets& gpu, const TechniqueOptions& /*options*/)
    : program_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})) {}

void ForwardTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  graph.add_pass("shading", [&](render::PassBuilder& pass) {
    render::read_shading_inputs(pass, frame);
    render::read_draws(pass, frame);
    pass.write(frame.scene_depth, render::Access::Attachment);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [this, &frame, &targets](const render::PassResources& res) {
    render::begin_scene_pass(res, frame, targets);
    program_.use();
    frame.draw_first_pass(res, render::draw_items);
  });
  render::add_transparency_pass(graph, program_, frame, targets);
}

}  // namespace atrium::techniques
