#include "render/light_buffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
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

// What keeps a light from being drawn; asked of every light every frame, so
// it builds no text (describe() does, for the few that fail).
enum class LightFault { None, Position, Rotation, Colour, Intensity, Radius, Animation };

// `moving`: its LightAnimation when the light moves on the GPU, which then
// places it rather than its Transform.
inline LightFault light_fault(const Transform& transform, const LightColor& light, const LightRadius* radius, bool directional,
                              const LightAnimation* moving) {
  if (moving && !(finite(moving->origin) && std::isfinite(moving->radius) && std::isfinite(moving->phase) &&
                  std::isfinite(moving->angular_speed))) {
    return LightFault::Animation;
  }
  if (!moving && !directional && !finite(transform.position)) return LightFault::Position;
  if (!finite(glm::vec3(transform.rotation.x, transform.rotation.y, transform.rotation.z)) || !std::isfinite(transform.rotation.w))
    return LightFault::Rotation;
  if (!finite(light.color) || light.color.r < 0.0f || light.color.g < 0.0f || light.color.b < 0.0f) return LightFault::Colour;
  if (!std::isfinite(light.intensity) || light.intensity < 0.0f) return LightFault::Intensity;
  if (radius && !directional && !(std::isfinite(radius->radius) && radius->radius > 0.0f)) return LightFault::Radius;
  return LightFault::None;
}

std::string describe(LightFault fault, const Transform& transform, const LightColor& light, const LightRadius* radius,
                     const LightAnimation* moving) {
  switch (fault) {
    case LightFault::Animation:
      return "animation (origin " + describe(moving->origin) + ", radius " + describe(moving->radius) + ", phase " +
             describe(moving->phase) + ", angular speed " + describe(moving->angular_speed) + ") is not finite";
    case LightFault::Position: return "position " + describe(transform.position) + " is not finite";
    case LightFault::Rotation: return "rotation is not finite";
    case LightFault::Colour: return "colour " + describe(light.color) + " is negative or not finite";
    case LightFault::Intensity: return "intensity " + describe(light.intensity) + " is negative or not finite";
    case LightFault::Radius: return "radius " + describe(radius ? radius->radius : 0.0f) + " is not a positive finite number";
    case LightFault::None: break;
  }
  return {};
}

}  // namespace

namespace {

// The pools of a light's other components, for one thread's walk over the
// LightColor pool in its order.
struct LightLookups {
  explicit LightLookups(const ecs::Registry& registry)
      : transform(registry.lookup<Transform>()),
        radius(registry.lookup<LightRadius>()),
        cone(registry.lookup<SpotCone>()),
        directional(registry.lookup<DirectionalLight>()),
        animation(registry.lookup<LightAnimation>()) {
    if (const auto* found = registry.try_resource<LightAnimationSettings>()) settings = *found;
  }
  ecs::Registry::Lookup<const Transform> transform;
  ecs::Registry::Lookup<const LightRadius> radius;
  ecs::Registry::Lookup<const SpotCone> cone;
  ecs::Registry::Lookup<const DirectionalLight> directional;
  ecs::Registry::Lookup<const LightAnimation> animation;
  LightAnimationSettings settings;
};

// The slots a light's other components hold, widened by each light visited.
struct SlotSpans {
  std::array<SlotRange, 5> slots;  // LightBlock::slots' order
  void add(std::size_t pool, std::uint32_t slot) {
    SlotRange& range = slots[pool];
    if (range.first == range.end) range = {slot, slot + 1};
    else range = {std::min(range.first, slot), std::max(range.end, slot + 1)};
  }
};

// Calls light(entity, gpu) when the entity holding `color` is a drawable
// light, rejected(entity, problem) when it is not; nothing when it has no
// Transform (it is no light). Notes in `spans` (when given) the slots its
// other components hold. Reads the registry only: several threads may call it
// at once, each with lookups of its own.
template <typename Light, typename Rejected>
void visit_light(LightLookups& pools, ecs::Entity entity, const LightColor& color, const Light& light, const Rejected& rejected,
                 SlotSpans* spans = nullptr) {
  const Transform* transform = pools.transform.find(entity);
  if (!transform) return;
  const LightRadius* radius = pools.radius.find(entity);
  const SpotCone* cone = pools.cone.find(entity);
  const bool directional = pools.directional.find(entity) != nullptr;
  const LightAnimation* animation = pools.animation.find(entity);
  if (spans) {
    spans->add(0, pools.transform.last_slot());
    if (radius) spans->add(1, pools.radius.last_slot());
    if (cone) spans->add(2, pools.cone.last_slot());
    if (directional) spans->add(3, pools.directional.last_slot());
    if (animation) spans->add(4, pools.animation.last_slot());
  }
  const LightAnimation* moving = animation && moves_on_gpu(pools.settings, cone != nullptr, directional) ? animation : nullptr;
  if (const LightFault fault = light_fault(*transform, color, radius, directional, moving); fault != LightFault::None) {
    rejected(entity, describe(fault, *transform, color, radius, moving));
    return;
  }
  GpuLightKind kind = directional ? GpuLightKind::Directional : cone ? GpuLightKind::Spot : GpuLightKind::Point;
  const float r = directional ? 0.0f : radius ? radius->radius : lighting::light_radius_from_intensity(color.color, color.intensity);
  GpuLight gpu{glm::vec4(transform->position, r), glm::vec4(color.color * color.intensity, static_cast<float>(kind)),
               glm::vec4(transform->rotation * glm::vec3(0.0f, 0.0f, -1.0f), 0.0f), glm::vec4(0.0f)};
  if (moving) gpu = with_motion(gpu, *moving);
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
// LightColor slots per LightBlock: what a frame skips or walks as one.
constexpr std::size_t kLightBlock = 1024;

// What lets a frame skip a block: the change clock the last walk took, and the
// staging indices a system patched after it (sorted).
struct SkipTest {
  std::uint64_t since = 0;
  std::span<const std::uint32_t> patched;

  [[nodiscard]] bool unchanged(const ecs::Registry& registry, const LightBlock& block, std::size_t first, std::size_t end,
                               std::size_t at) const {
    const auto patch = std::lower_bound(patched.begin(), patched.end(), at);
    if (patch != patched.end() && *patch < at + block.drawable) return false;
    auto written = [&](auto component, std::size_t pool) {
      const SlotRange range = block.slots[pool];
      return range.first != range.end && registry.written_since<decltype(component)>(range.first, range.end, since);
    };
    return !registry.written_since<LightColor>(first, end, since) && !written(Transform{}, 0) && !written(LightRadius{}, 1) &&
           !written(SpotCone{}, 2) && !written(DirectionalLight{}, 3) && !written(LightAnimation{}, 4);
  }
};

void mark_changed(std::vector<LightRun>& runs, std::size_t i) {
  if (!runs.empty() && i <= runs.back().end + kRunGap) runs.back().end = i + 1;
  else runs.push_back({i, i + 1});
}

// One thread's walk over its chunk of the LightColor pool, a block at a time:
// its lights go to the staging copy from chunk.offset on, each written where
// it differs from what is there or, from `compared_below` on,
// unconditionally; its changed indices noted in chunk.runs. With `skip`, a
// block that nothing wrote is left as it is (a walked block that holds
// another number of lights than before moves the ones after it, which are
// then walked too). It writes nothing from `limit` on, where the next thread
// writes: a chunk holding more lights than that has moved the next, whose
// lights are all walked again. Returns the light entities it visited.
std::size_t walk_chunk(const ecs::Registry& registry, LightBuffer& state, LightChunk& chunk, ShareRange pool_range, std::size_t limit,
                       std::size_t compared_below, const SkipTest* skip) {
  const std::span<const ecs::Entity> entities = registry.entities_with<LightColor>();
  const std::span<const LightColor> colors = registry.components_of<LightColor>();
  const std::size_t blocks = (pool_range.end - pool_range.begin + kLightBlock - 1) / kLightBlock;
  if (chunk.blocks.size() != blocks) skip = nullptr;
  chunk.blocks.resize(blocks);
  chunk.count = chunk.rejected_count = 0;
  chunk.runs.clear();
  chunk.rejected.clear();
  LightLookups pools(registry);
  std::size_t visited = 0;
  bool shifted = false;  // a walked block holds another number of lights than before
  for (std::size_t b = 0; b < blocks; ++b) {
    LightBlock& block = chunk.blocks[b];
    const std::size_t first = pool_range.begin + b * kLightBlock, end = std::min(pool_range.end, first + kLightBlock);
    if (skip && !shifted && skip->unchanged(registry, block, first, end, chunk.offset + chunk.count)) {
      chunk.count += block.drawable;
      chunk.rejected_count += block.rejected;
      continue;
    }
    const std::uint32_t drawable_before = block.drawable;
    const std::size_t count_before = chunk.count, rejected_before = chunk.rejected.size();
    SlotSpans spans;
    for (std::size_t p = first; p < end; ++p) {
      visit_light(pools, entities[p], colors[p], [&](ecs::Entity entity, const GpuLight& light) {
        const std::size_t i = chunk.offset + chunk.count++;
        if (i >= limit) return;
        if (i >= compared_below || std::memcmp(&state.staging[i], &light, sizeof(GpuLight)) != 0) {
          state.staging[i] = light;
          mark_changed(chunk.runs, i);
        }
        if (state.entities[i] != entity) state.entities[i] = entity;  // unchanged memory stays clean
      }, [&](ecs::Entity entity, std::string problem) { chunk.rejected.push_back({entity, std::move(problem)}); }, &spans);
    }
    visited += end - first;
    block.drawable = static_cast<std::uint32_t>(chunk.count - count_before);
    block.rejected = static_cast<std::uint32_t>(chunk.rejected.size() - rejected_before);
    block.slots = spans.slots;
    chunk.rejected_count += block.rejected;
    shifted = shifted || block.drawable != drawable_before;
  }
  return visited;
}

// The light pools' structure versions: lights added or removed, or given or
// losing a component, change them (and a frame then walks every light); and
// whether animations move on the GPU, which changes what a record holds.
std::array<std::uint64_t, 7> light_structure(const ecs::Registry& registry) {
  const auto* animations = registry.try_resource<LightAnimationSettings>();
  return {registry.structure_version<LightColor>(),      registry.structure_version<Transform>(),
          registry.structure_version<LightRadius>(),     registry.structure_version<SpotCone>(),
          registry.structure_version<DirectionalLight>(), registry.structure_version<LightAnimation>(),
          animations && animations->on_gpu ? 1u : 0u};
}

// Overwrites the buffer's staging copy with this frame's lights where they
// differ and returns the runs of indices that changed: the staging copy is
// what the GPU buffer holds (the shadow atlas keeps its patches in both), so
// only those runs need sending; a frame whose lights hold still sends
// nothing. The LightColor pool is walked in chunks, one thread each, each
// comparing with and writing into its own part of the staging copy: where
// last frame's chunk of the same pool began (or, new, where its pool range
// begins, as when no light is rejected). When no light entity was added or
// removed since `state.seen`, the chunks skip their blocks that nothing wrote.
// Lights rejected or made drawable since then move a chunk's start; that
// frame's chunks are walked again at their new starts, writing (and so
// sending) every light.
std::vector<LightRun> refresh_staging(const ecs::Registry& registry, LightBuffer& state, std::uint64_t now,
                                      std::vector<RejectedLight>& rejected) {
  const std::size_t total = registry.count<LightColor>();
  const std::size_t chunks = share_count(total, kLightsPerThread);
  const bool same_split = state.chunks.size() == chunks && state.pool_size == total;
  const std::array<std::uint64_t, 7> structure = light_structure(registry);
  std::sort(state.patched.begin(), state.patched.end());
  const SkipTest skip{state.seen, state.patched};
  const bool may_skip = same_split && state.seen != 0 && structure == state.structure;
  state.chunks.resize(chunks);
  state.pool_size = total;
  if (!same_split) {
    for (std::size_t c = 0; c < chunks; ++c) state.chunks[c].offset = share_range(total, chunks, c).begin;
  }
  const std::size_t kept = state.staging.size();
  state.staging.resize(std::max(kept, total));
  state.entities.resize(state.staging.size());
  std::vector<std::size_t> visited(chunks, 0);
  run_in_parallel(chunks, [&](std::size_t c) {
    const std::size_t limit = c + 1 < chunks ? state.chunks[c + 1].offset : state.staging.size();
    visited[c] = walk_chunk(registry, state, state.chunks[c], share_range(total, chunks, c), limit, kept, may_skip ? &skip : nullptr);
  });
  std::size_t count = 0;
  bool moved = false;
  for (LightChunk& chunk : state.chunks) {
    moved = moved || chunk.offset != count;
    chunk.offset = count;
    count += chunk.count;
  }
  if (moved) {
    run_in_parallel(chunks, [&](std::size_t c) {
      LightChunk& chunk = state.chunks[c];
      visited[c] += walk_chunk(registry, state, chunk, share_range(total, chunks, c), chunk.offset + chunk.count, 0, nullptr);
    });
  }
  state.walked = 0;
  for (const std::size_t v : visited) state.walked += static_cast<std::uint32_t>(v);
  state.seen = now;
  state.structure = structure;
  state.patched.clear();
  std::vector<LightRun> runs;
  for (const LightChunk& chunk : state.chunks) {
    for (const LightRun& run : chunk.runs) {
      if (!runs.empty() && run.begin <= runs.back().end + kRunGap) runs.back().end = run.end;
      else runs.push_back(run);
    }
    rejected.insert(rejected.end(), chunk.rejected.begin(), chunk.rejected.end());
  }
  state.staging.resize(count);
  state.entities.resize(count);
  return runs;
}

// The LightAnimation that with_motion put in a point light's record.
LightAnimation carried_motion(const GpuLight& light) {
  return LightAnimation{glm::vec3(light.direction), light.spot.x, light.direction.w, light.spot.y};
}

}  // namespace

GatheredLights gather_lights(ecs::Registry& registry) {
  GatheredLights gathered;
  const std::span<const ecs::Entity> entities = registry.entities_with<LightColor>();
  const std::span<const LightColor> colors = registry.components_of<LightColor>();
  gathered.lights.reserve(entities.size());
  LightLookups pools(registry);
  for (std::size_t i = 0; i < entities.size(); ++i) {
    visit_light(pools, entities[i], colors[i], [&](ecs::Entity entity, const GpuLight& light) {
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
    const std::uint64_t now = registry.advance_change_clock();
    std::vector<LightRun> runs = refresh_staging(std::as_const(registry), *state, now, rejected);
    state->rejected = 0;
    for (const LightChunk& chunk : state->chunks) state->rejected += static_cast<std::uint32_t>(chunk.rejected_count);
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
    if (state->uploaded > 0) ++state->sends;
  });
}

GpuLight with_motion(GpuLight light, const LightAnimation& animation) {
  light.position_radius = glm::vec4(animation.origin, light.position_radius.w);
  light.direction = glm::vec4(animation.origin, animation.radius);
  light.spot = glm::vec4(animation.phase, animation.angular_speed, light.spot.z, light.spot.w);
  return light;
}

bool moves_on_gpu(const GpuLight& light) {
  return light.color_kind.w == static_cast<float>(GpuLightKind::Point) && light.direction.w != 0.0f;
}

glm::vec3 moved_position(const GpuLight& light, double time) {
  if (!moves_on_gpu(light)) return glm::vec3(light.position_radius);
  return animated_position(carried_motion(light), time);
}

float motion_reach(const GpuLight& light) {
  return moves_on_gpu(light) ? animated_reach(carried_motion(light)) : 0.0f;
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
