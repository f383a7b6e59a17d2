#include "systems/shadows/shadow_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "systems/frustum_culling.hpp"
#include "systems/shadows/shadow_views.hpp"

namespace atrium::shadows {
namespace {

int next_power_of_two(float value) {
  int p = 1;
  while (static_cast<float>(p) < value && p < (1 << 30)) p *= 2;
  return p;
}

// The map side for a light `pixels` in radius on screen: one texel per pixel of
// its radius (a cube face spans 90 degrees, the light's sphere about as much
// of the screen as it fills), a power of two, kept while the light's size
// stays near the size it was given.
int map_resolution(float pixels, int previous, const AtlasLimits& limits) {
  int wanted = std::clamp(next_power_of_two(pixels), limits.min_tile, limits.max_tile);
  if (previous > 0 && wanted != previous) {
    const float p = static_cast<float>(previous);
    if (wanted > previous && pixels < p * 1.4f) wanted = previous;
    if (wanted < previous && pixels > p * 0.35f) wanted = previous;
  }
  return wanted;
}

}  // namespace

float light_importance(const GpuLight& light, const ViewState& view, glm::ivec2 viewport, float* pixels_radius) {
  const glm::vec3 color(light.color_kind);
  const float luminance = glm::dot(color, glm::vec3(0.2126f, 0.7152f, 0.0722f));
  const float screen_pixels = static_cast<float>(viewport.x) * static_cast<float>(viewport.y);
  if (static_cast<GpuLightKind>(light.color_kind.w) == GpuLightKind::Directional) {
    // Cascades cover the whole view at every size: as large as a tile may be.
    if (pixels_radius) *pixels_radius = std::numeric_limits<float>::max();
    return luminance > 0.0f ? std::numeric_limits<float>::max() : 0.0f;
  }
  const glm::vec3 centre(light.position_radius);
  const float radius = light.position_radius.w;
  if (!intersects(frustum_of(view.view_projection), centre, radius)) return 0.0f;
  const float distance = glm::length(centre - view.camera_position);
  float pixels = static_cast<float>(std::max(viewport.x, viewport.y));
  if (distance > radius * 1.0001f) {
    pixels = std::min(pixels, radius / std::sqrt(distance * distance - radius * radius) * view.projection[1][1] * 0.5f *
                                  static_cast<float>(viewport.y));
  }
  if (pixels_radius) *pixels_radius = pixels;
  const float coverage = std::min(1.0f, 3.14159265f * pixels * pixels / screen_pixels);
  return luminance * coverage;
}

std::vector<ShadowChoice> choose_shadowed_lights(std::span<const GpuLight> lights, std::span<const ecs::Entity> entities,
                                                 const ViewState& view, glm::ivec2 viewport, int count,
                                                 const PreviousShadows& previous, const AtlasLimits& limits) {
  std::vector<ShadowChoice> choices;
  if (count <= 0) return choices;
  std::vector<float> pixels(lights.size(), 0.0f);
  for (std::uint32_t i = 0; i < lights.size(); ++i) {
    float score = light_importance(lights[i], view, viewport, &pixels[i]);
    if (!(score > 0.0f)) continue;
    const ecs::Entity entity = i < entities.size() ? entities[i] : ecs::kNullEntity;
    if (!entity.is_null() && previous.count(entity) && score < std::numeric_limits<float>::max() / kKeepBonus) score *= kKeepBonus;
    choices.push_back({i, entity, 0, score});
  }
  // Most important first; ties by entity, so the order does not depend on the light buffer's.
  std::sort(choices.begin(), choices.end(), [](const ShadowChoice& a, const ShadowChoice& b) {
    return a.score != b.score ? a.score > b.score : a.entity < b.entity;
  });
  if (choices.size() > static_cast<std::size_t>(count)) choices.resize(static_cast<std::size_t>(count));

  auto faces = [&](const ShadowChoice& c) { return view_count(static_cast<GpuLightKind>(lights[c.light].color_kind.w)); };
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
