// Which lights get shadow maps this frame and how large: the K lights with the
// largest estimated contribution to the image (brightness times the share of
// the screen their sphere covers; a directional light always first), each map's
// side from the light's size on screen, all within the atlas. Lights shadowed
// last frame keep their place and size unless another light clearly outweighs
// them, so that shadows do not flicker as the camera moves (but for a camera
// cut, ViewState::cut, when the ShadowAtlas passes no last frame). Pure CPU.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "components/frame_resources.hpp"
#include "ecs/entity.hpp"
#include "render/light_buffer.hpp"

namespace atrium::shadows {

// A light shadowed last frame keeps its place over one with up to this much
// more estimated contribution, and its map size until its size on screen
// leaves [kKeepSize / 2, kKeepSize] times (the map size's next power of two).
inline constexpr float kKeepBonus = 1.5f;
// The most lights --shadows may ask for: 1024 point lights at the smallest
// tile fill 6.3 of the atlas's 16.8 million texels.
inline constexpr int kMaxShadowedLights = 1024;

struct AtlasLimits {
  int atlas_size = 4096;  // texels per side
  int min_tile = 32;
  int max_tile = 1024;
};

struct ShadowChoice {
  std::uint32_t light = 0;  // index into the frame's lights
  ecs::Entity entity;
  int resolution = 0;       // texels per side of each of its maps
  float score = 0.0f;       // its estimated contribution (with the bonus)
};

// What a light shadowed last frame had.
using PreviousShadows = std::unordered_map<ecs::Entity, int>;

// Up to `count` lights, most important first, their maps' areas adding up to at
// most the atlas (the least important are made smaller, then left out).
[[nodiscard]] std::vector<ShadowChoice> choose_shadowed_lights(std::span<const render::GpuLight> lights, std::span<const ecs::Entity> entities,
                                                               const ViewState& view, glm::ivec2 viewport, int count,
                                                               const PreviousShadows& previous, const AtlasLimits& limits);

}  // namespace atrium::shadows
