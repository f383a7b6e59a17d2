#include "systems/lighting/clustered.hpp"

#include "gfx/depth.hpp"

namespace atrium::lighting {
namespace {

std::vector<gfx::ShaderDefine> mark_defines(bool pixel_bounds) {
  if (pixel_bounds) return {};
  return {{"ACTIVE_FLAGS"}};
}

}  // namespace

ClusteredTechnique::ClusteredTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool deferred)
    : deferred_(deferred),
      pixel_bounds_(options.cluster_bounds == ClusterBounds::Pixels),
      active_only_(options.active_clusters && !pixel_bounds_),
      grid_(options.cluster_grid, options.z_slicing),
      assign_(ClusterGrid::assign_programs(gpu.shaders(), options.cluster_bounds, options.active_clusters)),
      mark_(gpu.shaders().get({"clustered/mark_active.comp"}, mark_defines(pixel_bounds_))),
      mark_blended_(gpu.shaders().get({"common/mesh.vert", "clustered/mark_blended.frag"}, mark_defines(pixel_bounds_))),
      geometry_(gpu.shaders().get({"common/mesh.vert", deferred ? "deferred/geometry.frag" : "common/depth_masked.frag"})),
      position_only_(gpu.shaders().get({"common/mesh.vert", "common/depth_only.frag"}, {{"POSITION_ONLY"}})),
      shading_(deferred ? SampleRatePrograms(gpu.shaders(), {"post/fullscreen.vert", "clustered/lighting.frag"}, {}, options.msaa)
                        : SampleRatePrograms(gpu.shaders(), {"common/mesh.vert", "clustered/shade.frag"}, {}, 1)),
      blended_(gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void ClusteredTechnique::resize(const FrameTargets& targets) {
  if (deferred_) gbuffer_.resize(targets.size, targets.depth_stencil);
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
  glBindTextureUnit(0, targets.depth_stencil);
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

void ClusteredTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  grid_.update(frame.projection, frame.near_plane, frame.far_plane);
  if (deferred_) {
    gbuffer_.draw_geometry(geometry_, frame);
  } else {
    const auto pass = frame.timer.scope("depth pre-pass");
    begin_scene_pass(frame, targets);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    draw_depth(frame.draws.opaque, position_only_, geometry_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  {
    const auto pass = frame.timer.scope("light assignment");
    const GLuint per_cluster = pixel_bounds_ || active_only_ ? mark_clusters(frame, targets) : 0;
    grid_.assign(assign_, static_cast<std::uint32_t>(frame.lights.size()), per_cluster);
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
      shading_.per_pixel().use();
      draw_items(frame.draws.opaque);
      glDepthMask(GL_TRUE);
      glDepthFunc(gfx::kDepthCloser);
    }
  }
  // Blended surfaces are shaded forward+ from the same lists: their clusters
  // were marked with the opaque pixels'.
  grid_.bind();
  draw_transparent(blended_, frame, targets);
}

}  // namespace atrium::lighting
