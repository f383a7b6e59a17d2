// Tiled deferred shading (mode `tiled-deferred`): after the G-buffer pass, a
// compute pass over 16x16-pixel tiles takes each tile's depth bounds from the
// depth buffer, culls the lights against the tile's frustum and writes per-tile
// light lists; the lighting pass shades each pixel with its tile's lights.
#pragma once

#include <memory>

#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/light_index_list.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

inline constexpr int kTileSize = 16;

class TiledTechnique final : public LightingTechnique {
 public:
  TiledTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets) override;
  void execute(const FrameContext& frame, const FrameTargets& targets) override;
  [[nodiscard]] const GBuffer* gbuffer() const override { return &gbuffer_; }

  [[nodiscard]] const LightIndexList& list() const { return *list_; }
  [[nodiscard]] glm::uvec2 tiles() const { return tiles_; }
  [[nodiscard]] ListStats light_lists() const override {
    return list_ ? ListStats{list_->last_total(), list_->overflow_frames()} : ListStats{};
  }
  [[nodiscard]] LightBins bind_light_bins() const override;

 private:
  gfx::ShaderProgram& geometry_;
  gfx::ShaderProgram& assign_;
  gfx::ShaderProgram& lighting_;
  gfx::ShaderProgram& forward_;
  GBuffer gbuffer_;
  glm::uvec2 tiles_{0};
  std::unique_ptr<LightIndexList> list_;
};

}  // namespace atrium::lighting
