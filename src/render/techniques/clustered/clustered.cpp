#include "render/techniques/clustered/clustered.hpp"

#include "gfx/depth.hpp"
#include "render/frame/scene_passes.hpp"

namespace atrium::techniques {
namespace {

// Forward+'s pre-pass with MSAA also writes the shading depth (common/shading_depth.glsl).
std::vector<gfx::ShaderDefine> prepass_defines(bool deferred, int samples, std::vector<gfx::ShaderDefine> defines) {
  if (!deferred && samples > 1) defines.push_back({"SHADING_DEPTH"});
  return defines;
}

}  // namespace

ClusteredTechnique::ClusteredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool deferred)
    : deferred_(deferred),
      clusters_(gpu.shaders(), options, deferred ? lighting::ClusterLights::Positions::GBuffer : lighting::ClusterLights::Positions::Depth),
      geometry_(gpu.shaders().get({"common/mesh.vert", deferred ? "deferred/geometry.frag" : "common/depth_masked.frag"},
                                  prepass_defines(deferred, options.msaa, {}))),
      position_only_(gpu.shaders().get({"common/mesh.vert", "common/depth_only.frag"},
                                       prepass_defines(deferred, options.msaa, {{"POSITION_ONLY"}}))),
      lighting_(deferred ? std::optional<lighting::LightingPass>(std::in_place, gpu.shaders(), "clustered/lighting", std::vector<gfx::ShaderDefine>{}, options)
                         : std::nullopt),
      shading_(deferred ? nullptr : &gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      blended_(gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa, lighting::lighting_edge_marks(options)) {}

void ClusteredTechnique::resize(const render::FrameTargets& targets) { clusters_.resize(targets.size); }

void ClusteredTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  shading_depth_ = {};
  if (deferred_) {
    render::add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  } else {
    graph.add_pass("depth pre-pass", [&](render::PassBuilder& pass) {
      render::read_draws(pass, frame);
      pass.write(frame.scene_depth, render::Access::Attachment);
      if (targets.samples > 1) shading_depth_ = pass.create("shading-depth", render::TextureDesc{GL_R32F, targets.size, targets.samples}, render::ViewKind::Depth);
    }, [this, &frame, &targets](const render::PassResources& res) { draw_prepass(res, frame, targets); });
  }
  const render::ResourceId lists = clusters_.begin_frame(graph, frame);
  graph.add_pass("light assignment", [&](render::PassBuilder& pass) {
    if (deferred_) gbuffer_.read_targets(pass);
    else pass.read(shading_depth_.valid() ? shading_depth_ : frame.scene_depth, render::Access::Sampled);
    pass.read(frame.light_buffer, render::Access::Storage);
    // The blended surfaces mark their clusters by drawing.
    if (!frame.draws.list().blended.empty()) render::read_draws(pass, frame);
    pass.write(lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) {
    clusters_.assign(res, frame, targets, [&] {
      if (deferred_) gbuffer_.bind_textures(res);
      else glBindTextureUnit(0, res.texture(shading_depth_.valid() ? shading_depth_ : frame.scene_depth));
    });
  });
  graph.add_pass(deferred_ ? "lighting" : "shading", [&](render::PassBuilder& pass) {
    if (deferred_) {
      lighting_->declare(pass, gbuffer_, frame);
    } else {
      pass.write(frame.scene_color, render::Access::Attachment);
      render::read_shading_inputs(pass, frame);
      render::read_draws(pass, frame);
    }
    pass.read(lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) { shade(res, frame, targets); });
  // Blended surfaces are shaded forward+ from the same lists: their clusters
  // were marked with the opaque pixels'.
  render::add_transparency_pass(graph, blended_, frame, targets, [&](render::PassBuilder& pass) { pass.read(lists, render::Access::Storage); },
                        [this] { clusters_.bind(); });
}

void ClusteredTechnique::draw_prepass(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  // Depth, and with MSAA the shading depth: the colour is the shading pass's to clear.
  const GLuint framebuffer = shading_depth_.valid() ? res.framebuffer({shading_depth_}, frame.scene_depth)
                                                    : res.framebuffer(std::span<const render::ResourceId>{}, frame.scene_depth);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  if (shading_depth_.valid()) {
    const float far = gfx::kDepthFar;
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &far);
  }
  render::begin_depth(framebuffer);
  frame.draw_first_pass(res, [&](std::span<const render::DrawBatch> batches, const render::CommandSource& source) {
    render::draw_depth(batches, source, position_only_, geometry_);
  });
}

void ClusteredTechnique::shade(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  clusters_.bind();
  if (deferred_) {
    lighting_->run(res, gbuffer_, frame, targets);
    return;
  }
  const GLuint framebuffer = render::scene_framebuffer(res, frame);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  const float background[] = {frame.background.r, frame.background.g, frame.background.b, 1.0f};
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, background);
  // Every visible fragment is shaded once: its depth is already there.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloserOrEqual);
  glDepthMask(GL_FALSE);
  shading_->use();
  render::draw_items(frame.draws.list().opaque, frame.draws.commands());
  glDepthMask(GL_TRUE);
  glDepthFunc(gfx::kDepthCloser);
}

}  // namespace atrium::techniques
