#include "render/light_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "components/light.hpp"
#include "components/transform.hpp"
#include "base/format.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium {
namespace {

std::string describe(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string describe(const glm::vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", v.x, v.y, v.z);
  return text;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Why a light cannot be drawn, or nothing when it can.
std::optional<std::string> light_problem(const Transform& transform, const LightColor& light, const LightRadius* radius,
                                         bool directional) {
  if (!directional && !finite(transform.position)) return "position " + describe(transform.position) + " is not finite";
  const glm::vec4 rotation(transform.rotation.x, transform.rotation.y, transform.rotation.z, transform.rotation.w);
  if (!finite(glm::vec3(rotation)) || !std::isfinite(rotation.w)) return "rotation is not finite";
  if (!finite(light.color) || glm::any(glm::lessThan(light.color, glm::vec3(0.0f))))
    return "colour " + describe(light.color) + " is negative or not finite";
  if (!std::isfinite(light.intensity) || light.intensity < 0.0f)
    return "intensity " + describe(light.intensity) + " is negative or not finite";
  if (radius && !directional && !(std::isfinite(radius->radius) && radius->radius > 0.0f))
    return "radius " + describe(radius->radius) + " is not a positive finite number";
  return std::nullopt;
}

}  // namespace

GatheredLights gather_lights(ecs::Registry& registry) {
  GatheredLights gathered;
  gathered.lights.reserve(registry.count<LightColor>());
  registry.view<Transform, LightColor>().each([&](ecs::Entity entity, const Transform& transform, const LightColor& light) {
    const LightRadius* radius = registry.try_get<LightRadius>(entity);
    const SpotCone* cone = registry.try_get<SpotCone>(entity);
    const bool directional = registry.has<DirectionalLight>(entity);
    if (auto problem = light_problem(transform, light, radius, directional)) {
      gathered.rejected.push_back({entity, std::move(*problem)});
      return;
    }
    GpuLightKind kind = directional ? GpuLightKind::Directional : cone ? GpuLightKind::Spot : GpuLightKind::Point;
    const float r = directional ? 0.0f : radius ? radius->radius : lighting::light_radius_from_intensity(light.color, light.intensity);
    GpuLight gpu{glm::vec4(transform.position, r), glm::vec4(light.color * light.intensity, static_cast<float>(kind)),
                 glm::vec4(transform.rotation * glm::vec3(0.0f, 0.0f, -1.0f), 0.0f), glm::vec4(0.0f)};
    if (cone) {
      // glTF's smooth spot falloff: clamp(cos * scale + offset, 0, 1)^2.
      const float cos_outer = std::cos(cone->outer_cone), cos_inner = std::cos(cone->inner_cone);
      const float scale = 1.0f / std::max(cos_inner - cos_outer, 1e-4f);
      gpu.spot = glm::vec4(scale, -cos_outer * scale, 0.0f, 0.0f);
    }
    gathered.lights.push_back(gpu);
    gathered.entities.push_back(entity);
  });
  return gathered;
}

void register_light_buffer(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Render, "light_buffer", [](ecs::Registry& registry) {
    LightBuffer* state = registry.try_resource<LightBuffer>();
    if (!state) state = &registry.set_resource<LightBuffer>();
    GatheredLights gathered = gather_lights(registry);
    state->staging = std::move(gathered.lights);
    state->entities = std::move(gathered.entities);
    state->rejected = static_cast<std::uint32_t>(gathered.rejected.size());
    for (const RejectedLight& rejected : gathered.rejected) {
      if (!state->warned.insert(rejected.entity).second) continue;
      std::fprintf(stderr, "warning: light entity %u left out: %s (a system wrote it; lights need a finite position, "
                   "a non-negative colour and intensity and a positive radius)\n", rejected.entity.index, rejected.problem.c_str());
    }
    state->count = static_cast<std::uint32_t>(state->staging.size());
    const std::size_t needed = std::max<std::size_t>(state->staging.size(), 1);
    // Where there are no storage buffers the compute-free tier reads the lights
    // from a texture (render/storage_free.hpp), and this buffer is a plain one.
    const std::uint64_t block =
        gfx::gl_features().storage_buffers ? gfx::storage_block_limit() : std::numeric_limits<std::uint64_t>::max();
    const std::size_t limit = static_cast<std::size_t>(std::min<std::uint64_t>(block / sizeof(GpuLight), std::numeric_limits<std::uint32_t>::max()));
    if (needed > limit) {
      throw gfx::ResourceLimitError(std::to_string(state->staging.size()) + " lights need a " +
                                    format_bytes(static_cast<double>(needed * sizeof(GpuLight))) + " light buffer, more than one storage buffer may hold here (" +
                                    format_bytes(static_cast<double>(block)) + ", GL_MAX_SHADER_STORAGE_BLOCK_SIZE); use fewer lights");
    }
    if (!state->buffer || needed > state->capacity) {
      state->capacity = std::min(std::max(needed, state->capacity * 2), limit);
      state->buffer = gfx::create_buffer();
      glNamedBufferData(state->buffer.id(), static_cast<GLsizeiptr>(state->capacity * sizeof(GpuLight)), nullptr, GL_DYNAMIC_DRAW);
    }
    if (!state->staging.empty()) {
      glNamedBufferSubData(state->buffer.id(), 0, static_cast<GLsizeiptr>(state->staging.size() * sizeof(GpuLight)),
                           state->staging.data());
    }
  });
}

std::uint32_t shadowed_light_count(std::span<const GpuLight> lights) {
  std::uint32_t count = 0;
  while (count < lights.size() && lights[count].spot.z > 0.5f) ++count;
  return count;
}

std::vector<std::uint32_t> directional_lights(std::span<const GpuLight> lights) {
  std::vector<std::uint32_t> indices;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (lights[i].color_kind.w == static_cast<float>(GpuLightKind::Directional)) indices.push_back(static_cast<std::uint32_t>(i));
  }
  return indices;
}

}  // namespace atrium
