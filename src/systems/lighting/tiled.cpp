#include "systems/lighting/tiled.hpp"

namespace atrium::lighting {

TiledTechnique::TiledTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options)
    : geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      assign_(gpu.shaders().get({"tiled/assign.comp"})),
      lighting_(gpu.shaders().get({"post/fullscreen.vert", "tiled/lighting.frag"})),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(options.gbuffer_layout) {}

void TiledTechnique::resize(const FrameTargets& targets) {
  gbuffer_.resize(targets.size, targets.depth_stencil);
  tiles_ = (glm::uvec2(targets.size) + glm::uvec2(kTileSize - 1)) / glm::uvec2(kTileSize);
  list_ = std::make_unique<LightIndexList>(tiles_.x * tiles_.y);
  for (gfx::ShaderProgram* program : {&assign_, &lighting_}) {
    program->set("u_tiles", tiles_);
    program->set("u_list_capacity", list_->capacity());
  }
}

void TiledTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  gbuffer_.draw_geometry(geometry_, frame);
  {
    const auto pass = frame.timer.scope("light culling");
    glBindTextureUnit(0, targets.depth_stencil);
    assign_.use();
    list_->assign([&] { glDispatchCompute(tiles_.x, tiles_.y, 1); },
                  [&](std::uint32_t capacity) {
                    assign_.set("u_list_capacity", capacity);
                    lighting_.set("u_list_capacity", capacity);
                  });
  }
  {
    const auto pass = frame.timer.scope("lighting");
    list_->bind();
    gbuffer_.draw_fullscreen(lighting_, targets);
  }
  draw_transparent(forward_, frame, targets);
}

LightingTechnique::LightBins TiledTechnique::bind_light_bins() const {
  if (!list_) return {};
  list_->bind();
  return {Binning::Tiles, tiles_, static_cast<std::uint32_t>(kTileSize), list_->overflow_capacity()};
}

}  // namespace atrium::lighting
