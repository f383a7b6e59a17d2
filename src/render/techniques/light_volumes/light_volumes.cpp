#include "render/techniques/light_volumes/light_volumes.hpp"

#include "render/frame/scene_passes.hpp"

#include "gfx/depth.hpp"
#include "gfx/gl_features.hpp"

namespace atrium::techniques {

LightVolumeTechnique::LightVolumeTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool instanced)
    : instanced_(instanced),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      unlit_(gpu.shaders(), {"post/fullscreen.vert", "light_volumes/unlit.frag"}, {}, options.msaa),
      directional_(gpu.shaders(), {"post/fullscreen.vert", "light_volumes/lighting.frag"}, {{"DIRECTIONAL_ONLY"}}, options.msaa),
      stencil_(gpu.shaders().get({"common/light_volume.vert", "light_volumes/stencil.frag"})),
      lighting_(gpu.shaders(), {"common/light_volume.vert", "light_volumes/lighting.frag"}, {}, options.msaa, sphere_),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {
  sphere_.prepare(stencil_);
}

void LightVolumeTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  render::add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  auto lights_scene = [&](render::PassBuilder& pass) {
    gbuffer_.read_targets(pass);
    render::read_shading_inputs(pass, frame);
    pass.write(frame.scene_color, render::Access::Attachment);
  };
  graph.add_pass("base", lights_scene,
                 [this, &frame, &targets](const render::PassResources& res) { gbuffer_.draw_fullscreen(res, unlit_, frame, targets); });
  if (std::vector<std::uint32_t> suns = render::directional_lights(frame.lights); !suns.empty()) {
    graph.add_pass("directional", lights_scene, [this, &frame, &targets, suns = std::move(suns)](const render::PassResources& res) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
      for (const std::uint32_t light : suns) {
        directional_.each([&](gfx::ShaderProgram& program) { program.set("u_light_index", light); });
        gbuffer_.draw_fullscreen(res, directional_, frame, targets);
      }
    });
  }
  // Stencil and lighting alternate per light, so they are one pass.
  graph.add_pass(instanced_ ? "volumes" : "volumes (stencil + lighting)", [&](render::PassBuilder& pass) {
    lights_scene(pass);
    pass.write(frame.scene_depth, render::Access::Attachment);  // its stencil
  }, [this, &frame](const render::PassResources& res) {
    gbuffer_.bind_textures(res);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    if (gfx::gl_features().depth_clamp) glEnable(GL_DEPTH_CLAMP);  // else common/clip.glsl clamps
    if (instanced_) draw_volumes_instanced(frame);
    else draw_volumes_with_stencil(frame);
    glBindVertexArray(0);
    if (gfx::gl_features().depth_clamp) glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glCullFace(GL_BACK);
    glDepthFunc(gfx::kDepthCloser);
    glDepthMask(GL_TRUE);
  });
  render::add_transparency_pass(graph, forward_, frame, targets);
}

// The volume count lives in the stencil bits below kEdgeStencilBit; with MSAA
// that bit marks the G-buffer's edge pixels, which are lit per sample.
void LightVolumeTechnique::draw_volumes_with_stencil(const render::FrameContext& frame) {
  const std::uint32_t shadowed = render::shadowed_light_count(frame.lights);
  glEnable(GL_STENCIL_TEST);
  glDepthMask(GL_FALSE);
  glStencilMask(lighting::kBelowEdgeBits);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    if (frame.lights[i].color_kind.w == static_cast<float>(render::GpuLightKind::Directional)) continue;
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
    // count is non-zero and reset it there for the next light. Edge pixels
    // first, per sample (stencil above the bare edge bit), so that the
    // per-pixel draw after them finds their counts reset.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glStencilOp(GL_KEEP, GL_ZERO, GL_ZERO);
    const lighting::SampleRatePrograms& lighting = lighting_.of(index, shadowed);
    lighting.each([&](gfx::ShaderProgram& program) {
      program.set("u_light_index", index);
      program.set("u_instanced", 0);
    });
    if (gfx::ShaderProgram* per_sample = lighting.per_sample()) {
      glStencilFunc(GL_LESS, lighting::kEdgeStencilBit, 0xff);
      per_sample->use();
      sphere_.draw();
    }
    glStencilFunc(GL_NOTEQUAL, 0, lighting::kBelowEdgeBits);
    lighting.per_pixel().use();
    sphere_.draw();
  }
  glStencilMask(0xff);
}

void LightVolumeTechnique::draw_volumes_instanced(const render::FrameContext& frame) {
  if (frame.lights.empty()) return;
  // Back faces at or behind the scene's depth: the surface is in front of the
  // sphere's far side, which includes every pixel inside the sphere.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthFartherOrEqual);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  lighting_.draw_instanced(sphere_, static_cast<std::uint32_t>(frame.lights.size()), render::shadowed_light_count(frame.lights));
}

}  // namespace atrium::techniques
