#include "systems/lighting/clustered.hpp"

#include "gfx/depth.hpp"
#include "systems/lighting/scene_passes.hpp"

namespace atrium::lighting {
namespace {

// Deferred marks from the G-buffer's positions, forward+ from depths.
std::vector<gfx::ShaderDefine> mark_defines(bool pixel_bounds, bool from_gbuffer) {
  std::vector<gfx::ShaderDefine> defines;
  if (!pixel_bounds) defines.push_back({"ACTIVE_FLAGS"});
  if (from_gbuffer) defines.push_back({"FROM_GBUFFER"});
  return defines;
}

// Forward+'s pre-pass with MSAA also writes the shading depth (common/shading_depth.glsl).
std::vector<gfx::ShaderDefine> prepass_defines(bool deferred, int samples, std::vector<gfx::ShaderDefine> defines) {
  if (!deferred && samples > 1) defines.push_back({"SHADING_DEPTH"});
  return defines;
}

}  // namespace

ClusteredTechnique::ClusteredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool deferred)
    : deferred_(deferred),
      pixel_bounds_(options.cluster_bounds == ClusterBounds::Pixels),
      active_only_(options.active_clusters && !pixel_bounds_),
      grid_(options.cluster_grid, options.z_slicing),
      assign_(ClusterGrid::assign_programs(gpu.shaders(), options.cluster_bounds, options.active_clusters)),
      mark_(gpu.shaders().get({"clustered/mark_active.comp"}, mark_defines(pixel_bounds_, deferred))),
      mark_blended_(gpu.shaders().get({"common/mesh.vert", "clustered/mark_blended.frag"}, mark_defines(pixel_bounds_, false))),
      geometry_(gpu.shaders().get({"common/mesh.vert", deferred ? "deferred/geometry.frag" : "common/depth_masked.frag"},
                                  prepass_defines(deferred, options.msaa, {}))),
      position_only_(gpu.shaders().get({"common/mesh.vert", "common/depth_only.frag"},
                                       prepass_defines(deferred, options.msaa, {{"POSITION_ONLY"}}))),
      shading_(deferred ? SampleRatePrograms(gpu.shaders(), {"post/fullscreen.vert", "clustered/lighting.frag"}, {}, options.msaa)
                        : SampleRatePrograms(gpu.shaders(), {"common/mesh.vert", "clustered/shade.frag"}, {}, 1)),
      blended_(gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void ClusteredTechnique::resize(const FrameTargets& targets) {
  if (deferred_) gbuffer_.resize(targets.size, targets.depth_stencil);
  if (deferred_ || targets.samples <= 1) return;
  shading_depth_ = gfx::create_render_target(GL_R32F, targets.size.x, targets.size.y, targets.samples);
  prepass_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(prepass_framebuffer_.id(), GL_COLOR_ATTACHMENT0, shading_depth_.id(), 0);
  glNamedFramebufferTexture(prepass_framebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, targets.depth_stencil, 0);
  gfx::require_complete(prepass_framebuffer_.id(), "clustered forward+ pre-pass");
}

GLuint ClusteredTechnique::mark_clusters(const FrameContext& frame, const FrameTargets& targets) {
  GLuint buffer = 0;
  if (pixel_bounds_) {
    grid_.clear_pixel_bounds();
    buffer = grid_.pixel_bounds_buffer();
  } else {
    const std::uint32_t zero = 0;
    glClearNamedBufferData(grid_.active_buffer(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    buffer = grid_.active_buffer();
  }
  grid_.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, buffer);
  if (deferred_) gbuffer_.bind_textures();
  else glBindTextureUnit(0, shading_depth_.id() != 0 ? shading_depth_.id() : targets.depth_stencil);
  mark_.use();
  glDispatchCompute((static_cast<GLuint>(targets.size.x) + 7) / 8, (static_cast<GLuint>(targets.size.y) + 7) / 8, 1);
  if (!frame.draws.blended.empty()) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
    glViewport(0, 0, targets.size.x, targets.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthCloser);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    mark_blended_.use();
    draw_items(frame.draws.blended);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  return buffer;
}

void ClusteredTechnique::add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) {
  grid_.update(frame.projection, frame.near_plane, frame.far_plane);
  std::vector<render::ResourceId> gbuffer;
  if (deferred_) {
    gbuffer = add_geometry_pass(graph, gbuffer_, geometry_, frame);
  } else {
    graph.add_pass("depth pre-pass", [&](render::PassBuilder& pass) { pass.write(frame.scene_depth, render::Access::Attachment); },
                   [this, &frame, &targets](const render::PassResources&) { draw_prepass(frame, targets); });
  }
  const render::ResourceId lists = grid_.list().import_into(graph, "cluster light lists");
  graph.add_pass("light assignment", [&](render::PassBuilder& pass) {
    if (deferred_) read_gbuffer(pass, gbuffer);
    else pass.read(frame.scene_depth, render::Access::Sampled);
    pass.read(frame.light_buffer, render::Access::Storage);
    pass.write(lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources&) {
    const GLuint per_cluster = pixel_bounds_ || active_only_ ? mark_clusters(frame, targets) : 0;
    grid_.assign(assign_, static_cast<std::uint32_t>(frame.lights.size()), per_cluster);
  });
  graph.add_pass(deferred_ ? "lighting" : "shading", [&](render::PassBuilder& pass) {
    if (deferred_) read_gbuffer(pass, gbuffer);
    pass.read(frame.light_buffer, render::Access::Storage);
    pass.read(lists, render::Access::Storage);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [this, &frame, &targets](const render::PassResources&) { shade(frame, targets); });
  // Blended surfaces are shaded forward+ from the same lists: their clusters
  // were marked with the opaque pixels'.
  add_transparency_pass(graph, blended_, frame, targets, [&](render::PassBuilder& pass) { pass.read(lists, render::Access::Storage); },
                        [this] { grid_.bind(); });
}

void ClusteredTechnique::draw_prepass(const FrameContext& frame, const FrameTargets& targets) {
  begin_scene_pass(frame, targets);
  const DrawBatches draw_prepass = [&](std::span<const DrawBatch> batches) { draw_depth(batches, position_only_, geometry_); };
  if (shading_depth_.id() != 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, prepass_framebuffer_.id());
    const float far = gfx::kDepthFar;
    glClearNamedFramebufferfv(prepass_framebuffer_.id(), GL_COLOR, 0, &far);
    frame.draw_first_pass(draw_prepass);
  } else {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    frame.draw_first_pass(draw_prepass);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
}

void ClusteredTechnique::shade(const FrameContext& frame, const FrameTargets& targets) {
  grid_.bind();
  if (deferred_) {
    gbuffer_.draw_fullscreen(shading_, targets);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  // Every visible fragment is shaded once: its depth is already there.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloserOrEqual);
  glDepthMask(GL_FALSE);
  shading_.per_pixel().use();
  draw_items(frame.draws.opaque);
  glDepthMask(GL_TRUE);
  glDepthFunc(gfx::kDepthCloser);
}

}  // namespace atrium::lighting
