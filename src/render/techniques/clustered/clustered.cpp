#include "render/techniques/clustered/clustered.hpp"

#include "gfx/depth.hpp"
#include "render/frame/scene_passes.hpp"
#include "render/lighting/cpu_light_lists.hpp"

namespace atrium::techniques {
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

ClusteredTechnique::ClusteredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool deferred)
    : deferred_(deferred),
      compute_free_(options.compute_free),
      // Pixel boxes and active flags are marked by compute and storage writes: the tier tests the grid's boxes.
      pixel_bounds_(options.cluster_bounds == ClusterBounds::Pixels && !compute_free_),
      active_only_(options.active_clusters && !pixel_bounds_ && !compute_free_),
      grid_size_(options.cluster_grid),
      z_slicing_(options.z_slicing),
      grid_(std::make_unique<lighting::ClusterGrid>(grid_size_.at({1, 1}), z_slicing_)),
      assign_(compute_free_ ? std::nullopt
                            : std::optional<lighting::LightAssignmentPrograms>(lighting::ClusterGrid::assign_programs(
                                  gpu.shaders(), pixel_bounds_ ? ClusterBounds::Pixels : ClusterBounds::Grid, active_only_, options.light_assignment))),
      mark_(compute_free_ ? nullptr : &gpu.shaders().get({"clustered/mark_active.comp"}, mark_defines(pixel_bounds_, deferred))),
      mark_blended_(compute_free_ ? nullptr
                                  : &gpu.shaders().get({"common/mesh.vert", "clustered/mark_blended.frag"}, mark_defines(pixel_bounds_, false))),
      geometry_(gpu.shaders().get({"common/mesh.vert", deferred ? "deferred/geometry.frag" : "common/depth_masked.frag"},
                                  prepass_defines(deferred, options.msaa, {}))),
      position_only_(gpu.shaders().get({"common/mesh.vert", "common/depth_only.frag"},
                                       prepass_defines(deferred, options.msaa, {{"POSITION_ONLY"}}))),
      lighting_(deferred ? std::optional<lighting::LightingPass>(std::in_place, gpu.shaders(), "clustered/lighting", std::vector<gfx::ShaderDefine>{}, options)
                         : std::nullopt),
      shading_(deferred ? nullptr : &gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      blended_(gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa) {}

void ClusteredTechnique::resize(const render::FrameTargets& targets) {
  const glm::uvec3 dims = grid_size_.at(targets.size);
  if (dims != grid_->dims()) grid_ = std::make_unique<lighting::ClusterGrid>(dims, z_slicing_);
}

GLuint ClusteredTechnique::mark_clusters(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
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
  if (deferred_) gbuffer_.bind_textures(res);
  else glBindTextureUnit(0, res.texture(shading_depth_.valid() ? shading_depth_ : frame.scene_depth));
  mark_->use();
  glDispatchCompute((static_cast<GLuint>(targets.size.x) + 7) / 8, (static_cast<GLuint>(targets.size.y) + 7) / 8, 1);
  if (!frame.draws.list().blended.empty()) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
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
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  return buffer;
}

void ClusteredTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  grid_->update(frame.projection, frame.near_plane, frame.far_plane);
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
  const render::ResourceId lists = grid_->list().import_into(graph, "cluster-light-lists", compute_free_ ? render::ViewKind::None : render::ViewKind::LightBins);
  // The light-bins view reads the GPU's lists: not on the compute-free tier.
  if (!compute_free_) graph.publish(lighting::LightBins{lighting::LightBins::Binning::Clusters, lists, {}, 0, &grid_->list(), grid_->uniform_buffer(), grid_->dims()});
  graph.add_pass("light assignment", [&](render::PassBuilder& pass) {
    if (deferred_) gbuffer_.read_targets(pass);
    else pass.read(shading_depth_.valid() ? shading_depth_ : frame.scene_depth, render::Access::Sampled);
    pass.read(frame.light_buffer, render::Access::Storage);
    // The blended surfaces mark their clusters by drawing.
    if (!frame.draws.list().blended.empty()) render::read_draws(pass, frame);
    pass.write(lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) {
    if (compute_free_) {
      cpu_lists_.upload(lighting::bin_lights_in_clusters(frame.lights, frame.view, *grid_));
      return;
    }
    const GLuint per_cluster = pixel_bounds_ || active_only_ ? mark_clusters(res, frame, targets) : 0;
    grid_->assign(*assign_, static_cast<std::uint32_t>(frame.lights.size()), per_cluster);
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
                        [this] { bind_lists(); });
}

void ClusteredTechnique::draw_prepass(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  render::begin_scene_pass(res, frame, targets);
  const render::BatchDrawer draw_prepass = [&](std::span<const render::DrawBatch> batches, const render::CommandSource& source) {
    render::draw_depth(batches, source, position_only_, geometry_);
  };
  if (shading_depth_.valid()) {
    const GLuint prepass_framebuffer = res.framebuffer({shading_depth_}, frame.scene_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, prepass_framebuffer);
    const float far = gfx::kDepthFar;
    glClearNamedFramebufferfv(prepass_framebuffer, GL_COLOR, 0, &far);
    frame.draw_first_pass(res, draw_prepass);
  } else {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    frame.draw_first_pass(res, draw_prepass);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
}

void ClusteredTechnique::bind_lists() const {
  if (!compute_free_) {
    grid_->bind();
    return;
  }
  glBindBufferBase(GL_UNIFORM_BUFFER, render::kClusterUniformBinding, grid_->uniform_buffer());
  cpu_lists_.bind();
}

void ClusteredTechnique::shade(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  bind_lists();
  if (deferred_) {
    lighting_->run(res, gbuffer_, frame, targets);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, render::scene_framebuffer(res, frame));
  glViewport(0, 0, targets.size.x, targets.size.y);
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
