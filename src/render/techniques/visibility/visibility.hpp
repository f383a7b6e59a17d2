// The visibility buffer (mode `visibility-buffer`; Burns and Hunt, "The
// Visibility Buffer", JCGT 2013): the geometry pass writes depth and each
// pixel's triangle identifier (R32UI, 4 bytes a pixel) and nothing else; a
// compute resolve then rebuilds each pixel's surface from the triangle in the
// GPU's geometry pools, evaluates the material with explicit gradients and
// shades it with the clustered light lists, storing the lit HDR result. How
// the resolve reaches the materials' textures is --material-binding: bound
// (a compute pass lists each material's 8x8 tiles, then one dispatch per
// material runs over them with its textures bound; the lists hold at most
// tiles x 64 x samples entries, whatever the materials) or bindless (one dispatch
// over every tile, textures by handle). The raster pipeline touches a pixel's
// material once, not once per overdraw, and no G-buffer travels between
// geometry and light. Blended surfaces are shaded forward+ from the same lists
// afterwards, as in clustered-deferred. With MSAA it stores an identifier a
// sample and shades each surface a pixel shows once. Needs compute shaders
// (the technique table's ModeNeeds).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "render/lighting/cluster_lights.hpp"
#include "render/techniques/technique.hpp"
#include "gfx/stream_buffer.hpp"
#include "render/frame/draw_list.hpp"

namespace atrium::techniques {

// A material's indirect dispatch (GL's DispatchIndirectCommand) and its range
// of the tile lists; twin of MaterialTiles in shaders/visibility/material_tiles.glsl.
struct MaterialTiles {
  std::uint32_t x = 0, y = 1, z = 1;
  std::uint32_t tile_count = 0, first_tile = 0, next_tile = 0;
};
static_assert(sizeof(MaterialTiles) == 24, "std430 packs six 32-bit words; GL reads the dispatch from the first three");

// A material's textures as bindless handles, by slot; twin of MaterialTextures
// in shaders/common/material.glsl (a uvec2 each).
struct MaterialTextures {
  std::array<GLuint64, render::kMaterialTextureSlots> handles{};
};
static_assert(sizeof(MaterialTextures) == 8 * render::kMaterialTextureSlots, "std430 packs the uvec2 handles tightly");

// The binding `options` ask for, Automatic resolved for the current context
// (bindless where it has ARB_bindless_texture). Throws gfx::ResourceLimitError
// when bindless is asked for where the context lacks the extension.
[[nodiscard]] MaterialBinding resolve_material_binding(const TechniqueOptions& options);

class VisibilityTechnique final : public LightingTechnique {
 public:
  VisibilityTechnique(render::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const render::FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;
  [[nodiscard]] ListStats light_lists() override { return cluster_list_stats(clusters_); }
  [[nodiscard]] std::string variant() const override;

 private:
  // The geometry pass's body: identifiers and depth, through draw_first_pass.
  void draw_identifiers(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  // Lists each material's tiles (and gives background pixels the background):
  // counts them per tile, scans the counts into ranges, scatters the tiles.
  void classify(const render::PassResources& res, const render::FrameContext& frame);
  // One indirect dispatch per material over its tiles.
  void resolve(const render::PassResources& res, const render::FrameContext& frame) const;
  // One dispatch over every tile, each material's textures by handle.
  void resolve_bindless(const render::PassResources& res, const render::FrameContext& frame);
  // Uploads the units of this frame's list, as drawn (after occlusion culling's phases).
  void upload_units(const render::DrawList& list);
  // Each material's batch as drawn, for its textures and samplers (null: drawn by none).
  [[nodiscard]] static std::vector<const render::DrawBatch*> batches_by_material(const render::DrawList& list);
  // Grows the dispatches to hold `materials` and the tile lists to hold what
  // every tile can show of them.
  void reserve_tiles(std::size_t materials);
  // The most materials one tile can show: the fewer of the materials there is
  // room for and its samples (a work group of classify_'s pixels, times the samples).
  [[nodiscard]] std::size_t tile_slots() const;
  [[nodiscard]] std::size_t tile_count() const { return std::size_t{tiles_.x} * tiles_.y; }
  // Sizes of tile_lists_ and tile_materials_, as allocated and as the graph imports them.
  [[nodiscard]] std::size_t tile_list_bytes() const;
  [[nodiscard]] std::size_t tile_material_bytes() const;
  // The units, the geometry pools, the tile lists, the identifiers and the lit targets.
  void bind_inputs(const render::PassResources& res, const render::FrameContext& frame) const;

  render::GpuAssets& gpu_;
  MaterialBinding binding_;  // --material-binding, resolved: Bound or Bindless
  gfx::ShaderProgram& identifiers_;         // batches without an alpha test: positions only
  gfx::ShaderProgram& identifiers_masked_;  // alpha-masked batches: the alpha test, then the identifier
  gfx::ShaderProgram& classify_;
  gfx::ShaderProgram& lists_;  // visibility/material_lists.comp: ranges and scatter
  gfx::ShaderProgram& resolve_;
  gfx::ShaderProgram& blended_;  // forward+ shading of blended surfaces (clustered/shade.frag)
  lighting::ClusterLights clusters_;
  glm::uvec2 tiles_{0};  // tiles per row and column, each a work group of classify_ (its layout is the one fact)
  int samples_ = 1;
  std::size_t material_capacity_ = 0;  // materials the dispatches hold room for
  gfx::Buffer dispatch_;               // MaterialTiles of each material ("material-dispatch")
  gfx::Buffer tile_lists_;             // the materials' lists of tiles, tile_slots() for each tile in all ("material-tiles")
  gfx::Buffer tile_materials_;         // each tile's count of materials, then the materials ("tile-materials")
  gfx::StreamBuffer units_;
  gfx::StreamBuffer material_textures_;  // bindless: MaterialTextures of each material
  std::size_t unit_count_ = 0;  // of this frame, after the head of units_
  render::ResourceId identifiers_target_;
  render::ResourceId shading_depth_;  // with MSAA: each sample's depth at its pixel centre
};

}  // namespace atrium::techniques
