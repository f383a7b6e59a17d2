#include "systems/lighting/forward.hpp"

namespace atrium::lighting {

ForwardTechnique::ForwardTechnique(assets::GpuAssets& gpu, const TechniqueOptions& /*options*/)
    : program_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})) {}

void ForwardTechnique::resize(const FrameTargets& /*targets*/) {}

void ForwardTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  {
    const auto pass = frame.timer.scope("shading");
    begin_scene_pass(frame, targets);
    program_.use();
    frame.draw_first_pass(draw_items);
  }

  draw_transparent(program_, frame, targets);
}

}  // namespace atrium::lighting
