// Clustered shading (modes `clustered-forward` and `clustered-deferred`): the
// frustum is cut into a 3D grid of clusters; a compute pass assigns each light
// to the clusters its sphere touches; shading then loops over the pixel's
// cluster's lights only. Forward+ runs a depth pre-pass and shades each visible
// fragment once; deferred shades from the G-buffer (fragment or compute,
// --lighting-stage). By default a cluster's lights
// are those touching the box of the pixels it holds this frame (read from the
// positions shading lights and from blended fragments); --cluster-bounds grid tests its whole
// frustum slice instead (render/lighting/cluster_lights.hpp). Blended surfaces
// are shaded forward+ from the same lists.
#pragma once

#include <memory>
#include <optional>

#include "render/lighting/cluster_lights.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class ClusteredTechnique final : public LightingTechnique {
 public:
  ClusteredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool deferred);
  // Sizes the grid for the frame (--cluster-grid in pixels follows the size).
  void resize(const render::FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

  [[nodiscard]] const lighting::ClusterGrid& grid() const { return clusters_.grid(); }
  [[nodiscard]] ListStats light_lists() override { return cluster_list_stats(clusters_); }

 private:
  // Forward+: the depth pre-pass (through FrameContext::draw_first_pass).
  void draw_prepass(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // The opaque surfaces lit from the lists: full-screen (deferred) or forward.
  void shade(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);

  bool deferred_;
  lighting::ClusterLights clusters_;
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
