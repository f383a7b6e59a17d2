#include "render/light_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "components/light.hpp"
#include "components/transform.hpp"
#include "base/format.hpp"
#include "base/parallel.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium::render {
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

namespace {

// Calls light(entity, gpu) when the entity holding `color` is a drawable
// light, rejected(entity, problem) when it is not; nothing when it has no
// Transform (it is no light). Reads the registry only: several threads may
// call it at once.
template <typename Light, typename Rejected>
void visit_light(const ecs::Registry& registry, ecs::Entity entity, const LightColor& color, const Light& light,
                 const Rejected& rejected) {
  const Transform* transform = registry.find<Transform>(entity);
  if (!transform) return;
  const LightRadius* radius = registry.find<LightRadius>(entity);
  const SpotCone* cone = registry.find<SpotCone>(entity);
  const bool directional = registry.find<DirectionalLight>(entity) != nullptr;
  if (auto problem = light_problem(*transform, color, radius, directional)) {
    rejected(entity, std::move(*problem));
    return;
  }
  GpuLightKind kind = directional ? GpuLightKind::Directional : cone ? GpuLightKind::Spot : GpuLightKind::Point;
  const float r = directional ? 0.0f : radius ? radius->radius : lighting::light_radius_from_intensity(color.color, color.intensity);
  GpuLight gpu{glm::vec4(transform->position, r), glm::vec4(color.color * color.intensity, static_cast<float>(kind)),
               glm::vec4(transform->rotation * glm::vec3(0.0f, 0.0f, -1.0f), 0.0f), glm::vec4(0.0f)};
  if (cone) {
    // glTF's smooth spot falloff: clamp(cos * scale + offset, 0, 1)^2.
    const float cos_outer = std::cos(cone->outer_cone), cos_inner = std::cos(cone->inner_cone);
    const float scale = 1.0f / std::max(cos_inner - cos_outer, 1e-4f);
    gpu.spot = glm::vec4(scale, -cos_outer * scale, 0.0f, 0.0f);
  }
  light(entity, gpu);
}

// Lights apart by fewer than this many unchanged ones are sent in one upload:
// a call costs more than a few hundred bytes of copying.
constexpr std::size_t kRunGap = 64;
// Below this many lights a second thread costs more than it saves.
constexpr std::size_t kLightsPerThread = 16384;

void mark_changed(std::vector<LightRun>& runs, std::size_t i) {
  if (!runs.empty() && i <= runs.back().end + kRunGap) runs.back().end = i + 1;
  else runs.push_back({i, i + 1});
}

// Overwrites the buffer's staging copy with this frame's lights where they
// differ and returns the runs of indices that changed: the staging copy is
// what the GPU buffer holds (the shadow atlas keeps its patches in both), so
// only those runs need sending; a frame whose lights hold still sends
// nothing. The lights are gathered and compared in chunks of the LightColor
// pool, one thread each, in pool order, into memory the buffer keeps.
std::vector<LightRun> refresh_staging(const ecs::Registry& registry, LightBuffer& state, std::vector<RejectedLight>& rejected) {
  const std::span<const ecs::Entity> entities = registry.entities_with<LightColor>();
  const std::span<const LightColor> colors = registry.components_of<LightColor>();
  const std::size_t total = entities.size();
  const std::size_t chunks = std::clamp<std::size_t>(total / kLightsPerThread, 1, hardware_threads());
  state.chunks.resize(chunks);
  run_in_parallel(chunks, [&](std::size_t c) {
    LightChunk& chunk = state.chunks[c];
    chunk.lights.clear();
    chunk.entities.clear();
    chunk.rejected.clear();
    for (std::size_t i = total * c / chunks; i < total * (c + 1) / chunks; ++i) {
      visit_light(registry, entities[i], colors[i], [&](ecs::Entity entity, const GpuLight& light) {
        chunk.lights.push_back(light);
        chunk.entities.push_back(entity);
      }, [&](ecs::Entity entity, std::string problem) { chunk.rejected.push_back({entity, std::move(problem)}); });
    }
  });
  std::size_t count = 0;
  for (LightChunk& chunk : state.chunks) {
    chunk.offset = count;
    count += chunk.lights.size();
  }
  const std::size_t kept = std::min(count, state.staging.size());
  state.staging.resize(count);
  state.entities.resize(count);
  run_in_parallel(chunks, [&](std::size_t c) {
    LightChunk& chunk = state.chunks[c];
    chunk.runs.clear();
    for (std::size_t j = 0; j < chunk.lights.size(); ++j) {
      const std::size_t i = chunk.offset + j;
      if (i >= kept || std::memcmp(&state.staging[i], &chunk.lights[j], sizeof(GpuLight)) != 0) {
        state.staging[i] = chunk.lights[j];
        mark_changed(chunk.runs, i);
      }
      state.entities[i] = chunk.entities[j];
    }
  });
  std::vector<LightRun> runs;
  for (const LightChunk& chunk : state.chunks) {
    for (const LightRun& run : chunk.runs) {
      if (!runs.empty() && run.begin <= runs.back().end + kRunGap) runs.back().end = run.end;
      else runs.push_back(run);
    }
    rejected.insert(rejected.end(), chunk.rejected.begin(), chunk.rejected.end());
  }
  return runs;
}

}  // namespace

GatheredLights gather_lights(ecs::Registry& registry) {
  GatheredLights gathered;
  const std::span<const ecs::Entity> entities = registry.entities_with<LightColor>();
  const std::span<const LightColor> colors = registry.components_of<LightColor>();
  gathered.lights.reserve(entities.size());
  for (std::size_t i = 0; i < entities.size(); ++i) {
    visit_light(registry, entities[i], colors[i], [&](ecs::Entity entity, const GpuLight& light) {
      gathered.lights.push_back(light);
      gathered.entities.push_back(entity);
    }, [&](ecs::Entity entity, std::string problem) { gathered.rejected.push_back({entity, std::move(problem)}); });
  }
  return gathered;
}

void register_light_buffer(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Render, "light_buffer", [](ecs::Registry& registry) {
    LightBuffer* state = registry.try_resource<LightBuffer>();
    if (!state) state = &registry.set_resource<LightBuffer>();
    std::vector<RejectedLight> rejected;
    std::vector<LightRun> runs = refresh_staging(std::as_const(registry), *state, rejected);
    state->rejected = static_cast<std::uint32_t>(rejected.size());
    for (const RejectedLight& light : rejected) {
      if (!state->warned.insert(light.entity).second) continue;
      std::fprintf(stderr, "warning: light entity %u left out: %s (a system wrote it; lights need a finite position, "
                   "a non-negative colour and intensity and a positive radius)\n", light.entity.index, light.problem.c_str());
    }
    state->count = static_cast<std::uint32_t>(state->staging.size());
    const std::size_t needed = std::max<std::size_t>(state->staging.size(), 1);
    // Where there are no storage buffers the compute-free tier reads the lights
    // from a texture (render/storage_free.hpp), and this buffer is a plain one.
    const std::uint64_t block =
        gfx::gl_features().storage_buffers ? gfx::storage_block_limit() : std::numeric_limits<std::uint64_t>::max();
    const std::size_t limit = static_cast<std::size_t>(std::min<std::uint64_t>(block / sizeof(GpuLight), std::numeric_limits<std::uint32_t>::max()));
    if (needed > limit) {
      // The staging copy no longer matches the buffer: the next frame sends it whole.
      state->buffer = {};
      state->capacity = 0;
      throw gfx::ResourceLimitError(std::to_string(state->staging.size()) + " lights need a " +
                                    format_bytes(static_cast<double>(needed * sizeof(GpuLight))) + " light buffer, more than one storage buffer may hold here (" +
                                    format_bytes(static_cast<double>(block)) + ", GL_MAX_SHADER_STORAGE_BLOCK_SIZE); use fewer lights");
    }
    if (!state->buffer || needed > state->capacity) {
      state->capacity = std::min(std::max(needed, state->capacity * 2), limit);
      state->buffer = gfx::create_buffer();
      glNamedBufferData(state->buffer.id(), static_cast<GLsizeiptr>(state->capacity * sizeof(GpuLight)), nullptr, GL_DYNAMIC_DRAW);
      runs = {{0, state->staging.size()}};
    }
    state->uploaded = 0;
    for (const LightRun& run : runs) {
      if (run.end <= run.begin) continue;
      glNamedBufferSubData(state->buffer.id(), static_cast<GLintptr>(run.begin * sizeof(GpuLight)),
                           static_cast<GLsizeiptr>((run.end - run.begin) * sizeof(GpuLight)), &state->staging[run.begin]);
      state->uploaded += static_cast<std::uint32_t>(run.end - run.begin);
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

}  // namespace atrium::render
