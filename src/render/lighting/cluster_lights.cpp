#include "render/lighting/cluster_lights.hpp"

#include "gfx/depth.hpp"
#include "gfx/pass_timer.hpp"
#include "render/frame/frame_draws.hpp"
#include "render/lighting/cpu_light_lists.hpp"

namespace atrium::lighting {
namespace {

// Marks read the G-buffer's positions or depths; without pixel boxes they set active flags.
std::vector<gfx::ShaderDefine> mark_defines(bool pixel_bounds, bool from_gbuffer) {
  std::vector<gfx::ShaderDefine> defines;
  if (!pixel_bounds) defines.push_back({"ACTIVE_FLAGS"});
  if (from_gbuffer) defines.push_back({"FROM_GBUFFER"});
  return defines;
}

}  // namespace

ClusterLights::ClusterLights(gfx::ShaderLibrary& shaders, const TechniqueOptions& options, Positions positions)
    : compute_free_(options.compute_free),
      // Pixel boxes and active flags are marked by compute and storage writes: the tier tests the grid's boxes.
      pixel_bounds_(options.cluster_bounds == ClusterBounds::Pixels && !compute_free_),
      active_only_(options.active_clusters && !pixel_bounds_ && !compute_free_),
      grid_size_(options.cluster_grid),
      z_slicing_(options.z_slicing),
      grid_(std::make_unique<ClusterGrid>(grid_size_.at({1, 1}), z_slicing_)) {
  if (compute_free_) return;
  assign_.emplace(ClusterGrid::assign_programs(shaders, pixel_bounds_ ? ClusterBounds::Pixels : ClusterBounds::Grid, active_only_,
                                               options.light_assignment));
  mark_ = &shaders.get({"clustered/mark_active.comp"}, mark_defines(pixel_bounds_, positions == Positions::GBuffer));
  mark_blended_ = &shaders.get({"common/mesh.vert", "clustered/mark_blended.frag"}, mark_defines(pixel_bounds_, false));
}

void ClusterLights::resize(glm::ivec2 size) {
  const glm::uvec3 dims = grid_size_.at(size);
  if (dims != grid_->dims()) grid_ = std::make_unique<ClusterGrid>(dims, z_slicing_);
}

render::ResourceId ClusterLights::begin_frame(render::FrameGraph& graph, const render::FrameContext& frame) {
  grid_->update(frame.projection, frame.near_plane, frame.far_plane);
  const render::ResourceId lists = grid_->list().import_into(graph, "cluster-light-lists", compute_free_ ? render::ViewKind::None : render::ViewKind::LightBins);
  // The light-bins view reads the GPU's lists: not on the compute-free tier.
  if (!compute_free_) graph.publish(LightBins{LightBins::Binning::Clusters, lists, {}, 0, &grid_->list(), grid_->uniform_buffer(), grid_->dims()});
  return lists;
}

GLuint ClusterLights::mark_clusters(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets,
                                    const std::function<void()>& bind_positions) {
  GLuint buffer = 0;
  if (pixel_bounds_) {
    grid_->clear_pixel_bounds();
    buffer = grid_->pixel_bounds_buffer();
  } else {
    const std::uint32_t zero = 0;
    glClearNamedBufferData(grid_->active_buffer(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    buffer = grid_->active_buffer();
  }
  grid_->bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kPerClusterBinding, buffer);
  // Blended surfaces mark first: the geometry before ran on the graphics
  // pipeline, so the marks' draw follows it there and the frame switches to
  // compute once, for the depth marks and the assignment (the marks are
  // atomic minima, maxima or flags: their order does not matter).
  if (!frame.draws.list().blended.empty()) {
    glBindFramebuffer(GL_FRAMEBUFFER, render::scene_framebuffer(res, frame));
    glViewport(0, 0, targets.size.x, targets.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthCloser);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    mark_blended_->use();
    render::draw_items(frame.draws.list().blended, frame.draws.commands());
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  bind_positions();
  mark_->use();
  glDispatchCompute((static_cast<GLuint>(targets.size.x) + 7) / 8, (static_cast<GLuint>(targets.size.y) + 7) / 8, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  return buffer;
}

void ClusterLights::assign(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets,
                           const std::function<void()>& bind_positions) {
  if (compute_free_) {
    cpu_lists_.upload(bin_lights_in_clusters(frame.lights, frame.view, *grid_));
    return;
  }
  GLuint per_cluster = 0;
  if (pixel_bounds_ || active_only_) {
    const gfx::PassTimer::Step step("mark");
    per_cluster = mark_clusters(res, frame, targets, bind_positions);
  }
  grid_->assign(*assign_, static_cast<std::uint32_t>(frame.lights.size()), per_cluster);
}

void ClusterLights::bind() const {
  if (!compute_free_) {
    grid_->bind();
    return;
  }
  glBindBufferBase(GL_UNIFORM_BUFFER, render::kClusterUniformBinding, grid_->uniform_buffer());
  cpu_lists_.bind();
}

}  // namespace atrium::lighting
