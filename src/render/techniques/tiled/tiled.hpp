// Tiled deferred shading (mode `tiled-deferred`): after the G-buffer pass, a
// compute pass over 16x16-pixel tiles takes each tile's frustum and depth
// bounds from the G-buffer's positions (the points the lighting pass shades),
// then each light writes itself into the lists of the tiles it touches; the
// lighting pass (fragment or compute, --lighting-stage) shades each pixel with
// its tile's lights.
// Blended surfaces get lists of their own, bounded by the depths of the glass in
// front of each tile's opaque surfaces, and are shaded forward from them.
// On the compute-free tier the lists come from the CPU (cpu_light_lists.hpp:
// each tile's frustum without depth bounds, which would take the depth buffer
// back), as textures (render/storage_free.hpp), one list for both.
#pragma once

#include <memory>
#include <optional>

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/lighting/light_index_list.hpp"
#include "render/storage_free.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

inline constexpr int kTileSize = 16;

// std430 twin of TileBounds in shaders/tiled/tiles.glsl.
struct TileBounds {
  glm::vec4 planes[4];  // side planes through the eye, normals inward (view space)
  glm::vec4 depths;     // x nearest, y farthest view depth; z 1 when the tile holds nothing
};
static_assert(sizeof(TileBounds) == 80, "must match TileBounds in shaders/tiled/tiles.glsl");

class TiledTechnique final : public LightingTechnique {
 public:
  TiledTechnique(render::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const render::FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

  [[nodiscard]] const lighting::LightIndexList& list() const { return *list_; }
  // The lists of blended surfaces (filled only in frames that draw some).
  // light_lists() counts both.
  [[nodiscard]] const lighting::LightIndexList& blended_list() const { return *blended_list_; }
  [[nodiscard]] glm::uvec2 tiles() const { return tiles_; }
  [[nodiscard]] ListStats light_lists() override;

 private:
  // Takes the tiles' bounds with `bounds` (its inputs bound), then culls
  // `light_count` lights into `list` against them.
  void assign_lights(lighting::LightIndexList& list, gfx::ShaderProgram& bounds, std::uint32_t light_count);
  // The frame's blended surfaces: their nearest depth over the opaque depth,
  // then their lists (their forward shading reads those lists).
  void cull_for_blended(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);

  // The compute-free tier: the lists from the CPU, for opaque and blended surfaces alike.
  void bin_on_cpu(const render::FrameContext& frame, const render::FrameTargets& targets);

  bool compute_free_;
  gfx::ShaderProgram& geometry_;
  gfx::ShaderProgram* bounds_;          // tiled/tile_bounds.comp, from the G-buffer (nullptr on the compute-free tier)
  std::optional<lighting::LightAssignmentPrograms> assign_;
  lighting::LightingPass lighting_;
  gfx::ShaderProgram& blended_depth_;   // depth only
  gfx::ShaderProgram* blended_bounds_;  // tiled/tile_bounds.comp, of blended surfaces
  gfx::ShaderProgram& blended_;         // forward shading from the blended lists
  lighting::GBuffer gbuffer_;
  glm::uvec2 tiles_{0};
  std::unique_ptr<lighting::LightIndexList> list_, blended_list_;
  gfx::Buffer tile_bounds_;             // per tile: TileBounds (shaders/tiled/tiles.glsl)
  bool blended_listed_ = false;         // this frame filled blended_list_
  render::ResourceId front_depth_;      // this frame's opaque depth with blended surfaces drawn over it
  render::ListTextures cpu_lists_;      // the compute-free tier's
};

}  // namespace atrium::techniques
