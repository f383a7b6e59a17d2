// The cameras a shadowed light renders its maps from: six cube faces for a
// point light, one cone for a spot light, cascades along the view for a
// directional light; and their record for the shaders (ShadowView), which
// shaders/common/shadows.glsl reads to find a surface's texel in the atlas.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "render/light_buffer.hpp"

namespace atrium::shadows {

// Texels the point faces and spot cones keep around what they must cover, so
// that the sampling kernel (3x3 bilinear taps) never reads another light's tile.
inline constexpr int kGuardTexels = 2;
// Cascades of a directional light's map, each a tile of its own.
inline constexpr int kCascades = 4;
// Where the cascade splits fall between uniform (0) and logarithmic (1).
inline constexpr float kCascadeSplitBlend = 0.75f;

// std430 twin of ShadowView in shaders/common/shadows.glsl.
struct ShadowView {
  glm::mat4 view_projection{1.0f};  // world to the map's clip space (reversed Z, like the camera)
  glm::vec4 rect{0.0f};             // xy: the tile's lower-left corner in atlas UV, zw: its size
  // x: a texel's width in metres (orthographic) or per metre of distance
  // (perspective); y: a cascade's farthest view depth; z: 1 perspective, 0 orthographic.
  glm::vec4 params{0.0f};
};
static_assert(sizeof(ShadowView) == 96, "must match ShadowView in shaders/common/shadows.glsl");

// How many views (atlas tiles) a light of this kind renders.
[[nodiscard]] int view_count(render::GpuLightKind kind);

// The view of one face, cone or cascade, without its tile (rect) filled in.
// `resolution` is the tile's side in texels.
[[nodiscard]] std::array<ShadowView, 6> point_views(const render::GpuLight& light, int resolution);
[[nodiscard]] ShadowView spot_view(const render::GpuLight& light, int resolution);

// What a directional light's cascades cover: the camera's view frustum from
// `near` to `far`, and the scene's box, whose every caster must reach the maps.
struct CascadeFrame {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  float near = 0.05f;
  float far = 200.0f;
  glm::vec3 scene_min{-1.0f};
  glm::vec3 scene_max{1.0f};
};
[[nodiscard]] std::array<ShadowView, kCascades> cascade_views(const render::GpuLight& light, const CascadeFrame& frame, int resolution);

}  // namespace atrium::shadows
