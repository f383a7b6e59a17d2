#include "systems/lighting/light_volumes.hpp"

#include "gfx/depth.hpp"

namespace atrium::lighting {

LightVolumeTechnique::LightVolumeTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool instanced)
    : instanced_(instanced),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      unlit_(gpu.shaders().get({"post/fullscreen.vert", "light_volumes/unlit.frag"})),
      directional_(gpu.shaders().get({"post/fullscreen.vert", "light_volumes/lighting.frag"}, {{"DIRECTIONAL_ONLY"}})),
      stencil_(gpu.shaders().get({"common/light_volume.vert", "light_volumes/stencil.frag"})),
      lighting_(gpu.shaders().get({"common/light_volume.vert", "light_volumes/lighting.frag"})),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(options.gbuffer_layout) {
  for (gfx::ShaderProgram* program : {&stencil_, &lighting_}) sphere_.prepare(*program);
}

void LightVolumeTechnique::resize(const FrameTargets& targets) { gbuffer_.resize(targets.size, targets.depth_stencil); }

void LightVolumeTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  gbuffer_.draw_geometry(geometry_, frame);
  {
    const auto pass = frame.timer.scope("base");
    gbuffer_.draw_fullscreen(unlit_, targets);
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  if (has_directional_light(frame.lights)) {
    const auto pass = frame.timer.scope("directional");
    gbuffer_.draw_fullscreen(directional_, targets);
  }
  {
    // Stencil and lighting alternate per light, so they are timed together.
    const auto pass = frame.timer.scope(instanced_ ? "volumes" : "volumes (stencil + lighting)");
    glEnable(GL_DEPTH_CLAMP);
    if (instanced_) draw_volumes_instanced(frame);
    else draw_volumes_with_stencil(frame);
    glBindVertexArray(0);
  }
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glCullFace(GL_BACK);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);

  draw_transparent(forward_, frame, targets);
}

void LightVolumeTechnique::draw_volumes_with_stencil(const FrameContext& frame) {
  glEnable(GL_STENCIL_TEST);
  glDepthMask(GL_FALSE);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    if (frame.lights[i].color_kind.w == static_cast<float>(GpuLightKind::Directional)) continue;
    const auto index = static_cast<unsigned>(i);
    // Stencil: no colour, depth test on, both faces; z-fail counting.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthCloser);
    glDisable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    stencil_.set("u_light_index", index);
    stencil_.set("u_instanced", 0);
    stencil_.use();
    sphere_.draw();
    // Lighting: back faces cover the volume's whole footprint; shade where the
    // stencil is non-zero and reset it there for the next light.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glStencilFunc(GL_NOTEQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_ZERO, GL_ZERO);
    lighting_.set("u_light_index", index);
    lighting_.set("u_instanced", 0);
    lighting_.use();
    sphere_.draw();
  }
}

void LightVolumeTechnique::draw_volumes_instanced(const FrameContext& frame) {
  if (frame.lights.empty()) return;
  // Back faces at or behind the scene's depth: the surface is in front of the
  // sphere's far side, which includes every pixel inside the sphere.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthFartherOrEqual);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  lighting_.set("u_instanced", 1);
  lighting_.use();
  sphere_.draw(static_cast<GLsizei>(frame.lights.size()));
}

}  // namespace atrium::lighting
