#include "render/shadows/shadow_selection.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "base/frustum.hpp"
#include "render/shadows/shadow_views.hpp"

namespace atrium::shadows {
namespace {

// The map side for a light `pixels` in radius on screen: one texel per pixel of
// its radius (a cube face spans 90 degrees, the light's sphere about as much
// of the screen as it fills), a power of two, kept while the light's size
// stays near the size it was given.
int map_resolution(float pixels, int previous, const AtlasLimits& limits) {
  // The limits are powers of two: rounding up within them stays within them.
  const float clamped = std::clamp(pixels, static_cast<float>(limits.min_tile), static_cast<float>(limits.max_tile));
  int wanted = static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::ceil(clamped))));
  if (previous > 0 && wanted != previous) {
    const float p = static_cast<float>(previous);
    if (wanted > previous && pixels < p * 1.4f) wanted = previous;
    if (wanted < previous && pixels > p * 0.35f) wanted = previous;
  }
  return wanted;
}

// The estimated contribution of one light to the image (0 when its sphere
// misses `frustum`, the view's) and its radius on screen in pixels. A light
// the GPU moves is estimated from its record's position (its origin): where
// the GPU puts it costs trigonometry per light, over as many as 2^20, each
// frame. Its sphere grown by how far it can stray meets the frustum wherever
// it is, so that no light moving into view is left out.
float light_importance(const render::GpuLight& light, const ViewState& view, const Frustum& frustum, glm::ivec2 viewport, float& pixels_radius) {
  const glm::vec3 color(light.color_kind);
  const float luminance = glm::dot(color, glm::vec3(0.2126f, 0.7152f, 0.0722f));
  const float screen_pixels = static_cast<float>(viewport.x) * static_cast<float>(viewport.y);
  if (static_cast<render::GpuLightKind>(light.color_kind.w) == render::GpuLightKind::Directional) {
    // Cascades cover the whole view at every size: as large as a tile may be.
    pixels_radius = std::numeric_limits<float>::max();
    return luminance > 0.0f ? std::numeric_limits<float>::max() : 0.0f;
  }
  const glm::vec3 centre(light.position_radius);
  const float radius = light.position_radius.w;
  if (!intersects(frustum, centre, radius + render::motion_reach(light))) return 0.0f;
  const float distance = glm::length(centre - view.camera_position);
  float pixels = static_cast<float>(std::max(viewport.x, viewport.y));
  if (distance > radius * 1.0001f) {
    pixels = std::min(pixels, radius / std::sqrt(distance * distance - radius * radius) * view.projection[1][1] * 0.5f *
                                  static_cast<float>(viewport.y));
  }
  pixels_radius = pixels;
  const float coverage = std::min(1.0f, glm::pi<float>() * pixels * pixels / screen_pixels);
  return luminance * coverage;
}

}  // namespace

std::vector<ShadowChoice> choose_shadowed_lights(std::span<const render::GpuLight> lights, std::span<const ecs::Entity> entities,
                                                 const ViewState& view, glm::ivec2 viewport, int count,
                                                 const PreviousShadows& previous, const AtlasLimits& limits) {
  std::vector<ShadowChoice> choices;
  if (count <= 0) return choices;
  const Frustum frustum = frustum_of(view.view_projection);
  std::vector<float> pixels(lights.size(), 0.0f);
  for (std::uint32_t i = 0; i < lights.size(); ++i) {
    float score = light_importance(lights[i], view, frustum, viewport, pixels[i]);
    if (!(score > 0.0f)) continue;
    const ecs::Entity entity = i < entities.size() ? entities[i] : ecs::kNullEntity;
    if (!entity.is_null() && previous.count(entity) && score < std::numeric_limits<float>::max() / kKeepBonus) score *= kKeepBonus;
    choices.push_back({i, entity, 0, score});
  }
  // The `count` most important, in order; ties by entity, so the order does
  // not depend on the light buffer's. A partial sort: a scene may hold a
  // million candidates for a handful of maps.
  const auto kept = std::min(choices.size(), static_cast<std::size_t>(count));
  std::partial_sort(choices.begin(), choices.begin() + static_cast<std::ptrdiff_t>(kept), choices.end(),
                    [](const ShadowChoice& a, const ShadowChoice& b) { return a.score != b.score ? a.score > b.score : a.entity < b.entity; });
  choices.resize(kept);

  auto faces = [&](const ShadowChoice& c) { return view_count(static_cast<render::GpuLightKind>(lights[c.light].color_kind.w)); };
  long long area = 0;
  for (ShadowChoice& c : choices) {
    const auto before = previous.find(c.entity);
    c.resolution = map_resolution(pixels[c.light], before == previous.end() ? 0 : before->second, limits);
    area += static_cast<long long>(faces(c)) * c.resolution * c.resolution;
  }
  // Over the atlas: halve the least important maps that can shrink, then leave
  // lights out. Power-of-two tiles within the atlas's area always pack.
  const long long capacity = static_cast<long long>(limits.atlas_size) * limits.atlas_size;
  while (area > capacity && !choices.empty()) {
    auto shrinkable = std::find_if(choices.rbegin(), choices.rend(), [&](const ShadowChoice& c) { return c.resolution > limits.min_tile; });
    if (shrinkable == choices.rend()) {
      area -= static_cast<long long>(faces(choices.back())) * choices.back().resolution * choices.back().resolution;
      choices.pop_back();
      continue;
    }
    area -= static_cast<long long>(faces(*shrinkable)) * shrinkable->resolution * shrinkable->resolution * 3 / 4;
    shrinkable->resolution /= 2;
  }
  return choices;
}

}  // namespace atrium::shadows
