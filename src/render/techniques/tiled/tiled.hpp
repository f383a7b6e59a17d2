// Tiled deferred shading (mode `tiled-deferred`): after the G-buffer pass, a
// compute pass over 16x16-pixel tiles takes each tile's depth bounds from the
// G-buffer's positions (the points the lighting pass shades), culls the lights against the tile's frustum and writes per-tile
// light lists; the lighting pass shades each pixel with its tile's lights.
// Blended surfaces get lists of their own, bounded by the depths of the glass in
// front of each tile's opaque surfaces, and are shaded forward from them.
#pragma once

#include <functional>
#include <memory>

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/light_index_list.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::lighting {

inline constexpr int kTileSize = 16;

class TiledTechnique final : public LightingTechnique {
 public:
  TiledTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) override;

  [[nodiscard]] const LightIndexList& list() const { return *list_; }
  // The lists of blended surfaces (filled only in frames that draw some).
  // light_lists() counts both.
  [[nodiscard]] const LightIndexList& blended_list() const { return *blended_list_; }
  [[nodiscard]] glm::uvec2 tiles() const { return tiles_; }
  [[nodiscard]] ListStats light_lists() override;

 private:
  // Give the programs that read the opaque (blended) list its new capacity.
  void set_capacity(std::uint32_t capacity);
  void set_blended_capacity(std::uint32_t capacity);
  // Culls `light_count` lights into `list` with `assign`; `set_capacity` keeps
  // the programs that read the list in step when it grows.
  void assign_lights(LightIndexList& list, gfx::ShaderProgram& assign, std::uint32_t light_count,
                     const std::function<void(std::uint32_t)>& set_capacity);
  // The frame's blended surfaces: their nearest depth over the opaque depth,
  // then their lists (their forward shading reads those lists).
  void cull_for_blended(const render::PassResources& res, const FrameContext& frame, const FrameTargets& targets);

  gfx::ShaderProgram& geometry_;
  gfx::ShaderProgram& assign_;
  SampleRatePrograms lighting_;
  gfx::ShaderProgram& blended_depth_;   // depth only
  gfx::ShaderProgram& assign_blended_;
  gfx::ShaderProgram& blended_;         // forward shading from the blended lists
  GBuffer gbuffer_;
  glm::uvec2 tiles_{0};
  std::unique_ptr<LightIndexList> list_, blended_list_;
  bool blended_listed_ = false;         // this frame filled blended_list_
  render::ResourceId front_depth_;      // this frame's opaque depth with blended surfaces drawn over it
};

}  // namespace atrium::lighting
