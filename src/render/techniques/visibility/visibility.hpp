// The visibility buffer (mode `visibility-buffer`; Burns and Hunt, "The
// Visibility Buffer", JCGT 2013): the geometry pass writes depth and each
// pixel's triangle identifier (R32UI, 4 bytes a pixel) and nothing else; a
// compute pass lists each material's 8x8 tiles; one compute dispatch per
// material then rebuilds each of its pixels' surface from the triangle in the
// GPU's geometry pools, evaluates the material with explicit gradients and
// shades it with the clustered light lists, storing the lit HDR result. The
// raster pipeline touches a pixel's material once, not once per overdraw, and
// no G-buffer travels between geometry and light. Blended surfaces are shaded
// forward+ from the same lists afterwards, as in clustered-deferred. With
// MSAA it stores an identifier a sample and shades each surface a pixel
// shows once. Needs compute shaders (the technique table's ModeNeeds).
#pragma once

#include "render/lighting/cluster_lights.hpp"
#include "render/techniques/technique.hpp"
#include "gfx/stream_buffer.hpp"

namespace atrium::techniques {

// GL's DispatchIndirectCommand; twin of Dispatch in shaders/visibility/material_tiles.glsl.
struct DispatchCommand {
  std::uint32_t x = 0, y = 1, z = 1;
};
static_assert(sizeof(DispatchCommand) == 12, "GL reads indirect dispatches as three 32-bit words");

class VisibilityTechnique final : public LightingTechnique {
 public:
  VisibilityTechnique(render::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const render::FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;
  [[nodiscard]] ListStats light_lists() override { return cluster_list_stats(clusters_); }

 private:
  // The geometry pass's body: identifiers and depth, through draw_first_pass.
  void draw_identifiers(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // Lists each material's tiles (and gives background pixels the background).
  void classify(const render::PassResources& res, const render::FrameContext& frame);
  // One indirect dispatch per material over its tiles.
  void resolve(const render::PassResources& res, const render::FrameContext& frame) const;
  // Grows the tile lists to hold `materials` lists of every tile.
  void reserve_tiles(std::size_t materials);
  // The units, the geometry pools, the tile lists, the identifiers and the lit targets.
  void bind_inputs(const render::PassResources& res, const render::FrameContext& frame) const;

  render::GpuAssets& gpu_;
  gfx::ShaderProgram& identifiers_;         // batches without an alpha test: positions only
  gfx::ShaderProgram& identifiers_masked_;  // alpha-masked batches: the alpha test, then the identifier
  gfx::ShaderProgram& classify_;
  gfx::ShaderProgram& resolve_;
  gfx::ShaderProgram& blended_;  // forward+ shading of blended surfaces (clustered/shade.frag)
  lighting::ClusterLights clusters_;
  glm::uvec2 tiles_{0};  // tiles per row and column, each a work group of classify_ (its layout is the one fact)
  std::size_t tile_materials_ = 0;  // materials the tile lists hold room for
  gfx::Buffer dispatch_, tile_lists_;
  gfx::StreamBuffer units_;
  std::size_t unit_count_ = 0;  // of this frame, at the start of units_
  render::ResourceId identifiers_target_;
  render::ResourceId shading_depth_;  // with MSAA: each sample's depth at its pixel centre
};

}  // namespace atrium::techniques
