#include "systems/lighting/forward.hpp"

namespace atrium::lighting {

ForwardTechnique::ForwardTechnique(assets::GpuAssets& gpu)
    : program_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})) {}

void ForwardTechnique::resize(const FrameTargets& /*targets*/) {}

void ForwardTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  {
  const auto pass = frame.timer.scope("shading");
  glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  const float clear_color[] = {frame.background.r, frame.background.g, frame.background.b, 1.0f};
  glClearNamedFramebufferfv(targets.hdr_framebuffer, GL_COLOR, 0, clear_color);
  glClearNamedFramebufferfi(targets.hdr_framebuffer, GL_DEPTH_STENCIL, 0, 1.0f, 0);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  program_.use();
  draw_items(program_, frame.gpu, frame.draws.opaque);
  }

  draw_transparent(program_, frame, targets);
}

}  // namespace atrium::lighting
