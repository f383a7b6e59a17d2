#include "render/techniques/light_prepass/light_prepass.hpp"

#include <string>

#include "render/frame/scene_passes.hpp"

#include "gfx/depth.hpp"
#include "gfx/gl_features.hpp"

namespace atrium::techniques {
namespace {

std::vector<gfx::ShaderDefine> with(std::vector<gfx::ShaderDefine> defines, std::vector<gfx::ShaderDefine> more) {
  defines.insert(defines.end(), more.begin(), more.end());
  return defines;
}

}  // namespace

LightPrepassTechnique::LightPrepassTechnique(render::GpuAssets& gpu, const TechniqueOptions& options)
    : gbuffer_(gpu.shaders(), GBufferLayout::Thin, options.msaa),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"}, gbuffer_.defines())),
      directional_(gpu.shaders(), {"post/fullscreen.vert", "light_prepass/accumulate.frag"},
                   with(gbuffer_.defines(), {{"DIRECTIONAL_ONLY"}}), options.msaa),
      volumes_(gpu.shaders(), {"common/light_volume.vert", "light_prepass/accumulate.frag"}, gbuffer_.defines(), options.msaa,
               sphere_),
      material_(gpu.shaders(), {"common/mesh.vert", "light_prepass/shade.frag"}, {}, options.msaa),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})) {
}

void LightPrepassTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  render::add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  graph.add_pass("light buffer", [&](render::PassBuilder& pass) {
    gbuffer_.read_targets(pass);
    render::read_shading_inputs(pass, frame);
    // The scene's depth, for the volumes' depth test (it is not sampled: the
    // distance comes from the thin G-buffer).
    pass.read(frame.scene_depth, render::Access::Attachment);
    for (std::size_t i = 0; i < light_buffer_.size(); ++i) {
      light_buffer_[i] = pass.create(std::string("light-buffer.") + kLightBufferTargets[i],
                                     render::TextureDesc{kLightBufferFormat, targets.size, targets.samples}, render::ViewKind::Color);
    }
  }, [this, &frame, &targets](const render::PassResources& res) { accumulate_lights(res, frame, targets); });
  graph.add_pass("material", [&](render::PassBuilder& pass) {
    for (const render::ResourceId sum : light_buffer_) pass.read(sum, render::Access::Sampled);
    render::read_draws(pass, frame);
    pass.write(frame.scene_depth, render::Access::Attachment);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [this, &frame, &targets](const render::PassResources& res) { shade_materials(res, frame, targets); });
  render::add_transparency_pass(graph, forward_, frame, targets);
}

void LightPrepassTechnique::accumulate_lights(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  const GLuint framebuffer = res.framebuffer(light_buffer_, frame.scene_depth);
  const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (GLint i = 0; i < static_cast<GLint>(light_buffer_.size()); ++i) glClearNamedFramebufferfv(framebuffer, GL_COLOR, i, zero);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  gbuffer_.bind_textures(res);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDepthMask(GL_FALSE);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  for (const std::uint32_t light : render::directional_lights(frame.lights)) {
    directional_.draw([&](gfx::ShaderProgram& program) {
      program.set("u_light_index", light);
      program.use();
      fullscreen_.draw();
    });
  }
  if (!frame.lights.empty()) {
    // As light-volumes-instanced: every sphere's back faces at or behind the
    // scene's depth cover the pixels inside it, the camera inside one
    // included; depth clamp keeps spheres that cross the near or far plane whole.
    if (gfx::gl_features().depth_clamp) glEnable(GL_DEPTH_CLAMP);  // else common/clip.glsl clamps
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthFartherOrEqual);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    volumes_.draw_instanced(sphere_, static_cast<std::uint32_t>(frame.lights.size()), render::shadowed_light_count(frame.lights));
    glBindVertexArray(0);
    if (gfx::gl_features().depth_clamp) glDisable(GL_DEPTH_CLAMP);
    glCullFace(GL_BACK);
  }
  glDisable(GL_BLEND);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
}

void LightPrepassTechnique::shade_materials(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  // Pixels no surface covers keep the background and no light.
  const GLfloat background[] = {frame.background.r, frame.background.g, frame.background.b, 1.0f};
  glClearNamedFramebufferfv(render::scene_framebuffer(res, frame), GL_COLOR, 0, background);
  glBindFramebuffer(GL_FRAMEBUFFER, render::lighting_framebuffer(res, frame));
  glViewport(0, 0, targets.size.x, targets.size.y);
  // Each visible fragment is shaded once: the first pass left its depth.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloserOrEqual);
  glDepthMask(GL_FALSE);
  glDisable(GL_BLEND);
  // Units 0-4 are the materials' textures.
  for (std::size_t i = 0; i < light_buffer_.size(); ++i) glBindTextureUnit(5 + static_cast<GLuint>(i), res.texture(light_buffer_[i]));
  material_.draw([&](gfx::ShaderProgram& program) {
    program.use();
    render::draw_items(frame.draws.list().opaque, frame.draws.commands());
  });
  glDepthMask(GL_TRUE);
  glDepthFunc(gfx::kDepthCloser);
}

}  // namespace atrium::techniques
