#include "systems/lighting/clustered.hpp"

#include "gfx/depth.hpp"

namespace atrium::lighting {
ClusteredTechnique::ClusteredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool deferred)
    : deferred_(deferred),
      active_only_(options.active_clusters),
      grid_(options.cluster_grid),
      assign_(ClusterGrid::assign_programs(gpu.shaders(), options.active_clusters)),
      mark_active_(gpu.shaders().get({"clustered/mark_active.comp"})),
      geometry_(gpu.shaders().get({"common/mesh.vert", deferred ? "deferred/geometry.frag" : "clustered/depth.frag"})),
      shading_(deferred ? gpu.shaders().get({"post/fullscreen.vert", "clustered/lighting.frag"})
                        : gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(options.gbuffer_layout) {}

void ClusteredTechnique::resize(const FrameTargets& targets) {
  if (deferred_) gbuffer_.resize(targets.size, targets.depth_stencil);
}

void ClusteredTechnique::mark_active_clusters(const FrameTargets& targets) {
  const std::uint32_t zero = 0;
  glClearNamedBufferData(grid_.active_buffer(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  grid_.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, grid_.active_buffer());
  glBindTextureUnit(0, targets.depth_stencil);
  mark_active_.use();
  glDispatchCompute((static_cast<GLuint>(targets.size.x) + 7) / 8, (static_cast<GLuint>(targets.size.y) + 7) / 8, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ClusteredTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  grid_.update(frame.projection, frame.near_plane, frame.far_plane);
  if (deferred_) {
    gbuffer_.draw_geometry(geometry_, frame);
  } else {
    const auto pass = frame.timer.scope("depth pre-pass");
    begin_scene_pass(frame, targets);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    geometry_.use();
    draw_items(geometry_, frame.gpu, frame.draws.opaque);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  {
    const auto pass = frame.timer.scope("light assignment");
    if (active_only_) mark_active_clusters(targets);
    grid_.assign(assign_, static_cast<std::uint32_t>(frame.lights.size()), active_only_ ? grid_.active_buffer() : 0);
  }
  {
    const auto pass = frame.timer.scope(deferred_ ? "lighting" : "shading");
    grid_.bind();
    if (deferred_) {
      gbuffer_.draw_fullscreen(shading_, targets);
    } else {
      glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
      glViewport(0, 0, targets.size.x, targets.size.y);
      // Every visible fragment is shaded once: its depth is already there.
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(gfx::kDepthCloserOrEqual);
      glDepthMask(GL_FALSE);
      shading_.use();
      draw_items(shading_, frame.gpu, frame.draws.opaque);
      glDepthMask(GL_TRUE);
      glDepthFunc(gfx::kDepthCloser);
    }
  }
  draw_transparent(forward_, frame, targets);
}

}  // namespace atrium::lighting
