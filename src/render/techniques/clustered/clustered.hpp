// Clustered shading (modes `clustered-forward` and `clustered-deferred`): the
// frustum is cut into a 3D grid of clusters; a compute pass assigns each light
// to the clusters its sphere touches; shading then loops over the pixel's
// cluster's lights only. Forward+ runs a depth pre-pass and shades each visible
// fragment once; deferred shades from the G-buffer (fragment or compute,
// --lighting-stage). By default a cluster's lights
// are those touching the box of the pixels it holds this frame (read from the
// positions shading lights and from blended fragments); --cluster-bounds grid tests its whole
// frustum slice instead. Blended surfaces are shaded forward+ from the same lists.
// On the compute-free tier the lists come from the CPU (grid bounds:
// cpu_light_lists.hpp) as textures (render/storage_free.hpp).
#pragma once

#include <memory>
#include <optional>

#include "render/lighting/cluster_grid.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/storage_free.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class ClusteredTechnique final : public LightingTechnique {
 public:
  ClusteredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool deferred);
  // Sizes the grid for the frame (--cluster-grid in pixels follows the size).
  void resize(const render::FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

  [[nodiscard]] const lighting::ClusterGrid& grid() const { return *grid_; }
  [[nodiscard]] ListStats light_lists() override {
    if (compute_free_) return {cpu_lists_.entries(), 0};
    grid_->list().poll();
    return {grid_->list().last_total(), grid_->list().overflow_frames(), grid_->list().last_assignment(), grid_->list().last_density()};
  }

 private:
  // Fills the per-cluster buffer assignment reads (pixel boxes, or active
  // flags) from the positions shading will light (G-buffer, or depths) and the
  // blended fragments in front of them; returns it.
  GLuint mark_clusters(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // Forward+: the depth pre-pass (through FrameContext::draw_first_pass).
  void draw_prepass(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // The opaque surfaces lit from the lists: full-screen (deferred) or forward.
  void shade(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // Binds the grid's uniforms and its lists (the GPU's, or the CPU's textures).
  void bind_lists() const;

  bool deferred_;
  bool compute_free_;
  bool pixel_bounds_;
  bool active_only_;
  ClusterGridSize grid_size_;
  ZSlicing z_slicing_;
  std::unique_ptr<lighting::ClusterGrid> grid_;  // sized by resize()
  std::optional<lighting::LightAssignmentPrograms> assign_;  // none on the compute-free tier
  gfx::ShaderProgram* mark_;                    // nullptr on the compute-free tier
  gfx::ShaderProgram* mark_blended_;
  render::ListTextures cpu_lists_;              // the compute-free tier's
  gfx::ShaderProgram& geometry_;  // deferred: G-buffer pass; forward+: depth pre-pass of alpha-masked batches
  gfx::ShaderProgram& position_only_;  // forward+: depth pre-pass of the other batches
  std::optional<lighting::LightingPass> lighting_;  // deferred: the full-screen lighting (fragment or compute)
  gfx::ShaderProgram* shading_;           // forward+: forward shading of opaque surfaces
  gfx::ShaderProgram& blended_;   // forward+ shading of blended surfaces
  lighting::GBuffer gbuffer_;
  // Forward+ with MSAA: this frame's pre-pass depth at pixel centres (R32F,
  // per sample), where shading lights each fragment; assignment marks from it.
  render::ResourceId shading_depth_;
};

}  // namespace atrium::techniques
