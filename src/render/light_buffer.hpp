// The LightBuffer system (Render phase, before the MeshRenderer): mirrors every
// light entity (Transform + LightColor; optional LightRadius, SpotCone,
// DirectionalLight) into one shader storage buffer each frame, sending only the
// lights that changed since the last frame, and walking only the blocks of
// lights that something wrote (the registry's change detection): lights that
// hold still cost nothing a frame. Point lights that move on the GPU
// (LightAnimationSettings::on_gpu) hold still here: their records carry the
// motion (with_motion), which the light animation's pass plays. The buffer grows
// geometrically up to what one storage buffer may hold (gfx::storage_block_limit),
// beyond which the frame is refused with gfx::ResourceLimitError. Lights whose
// values cannot be drawn (NaN, infinite, negative) are left out with a warning.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include <glm/glm.hpp>

#include "components/light.hpp"
#include "ecs/scheduler.hpp"
#include "gfx/gl_object.hpp"

namespace atrium::render {

enum class GpuLightKind : std::uint32_t { Point = 0, Spot = 1, Directional = 2 };

// std430 twin of Light in shaders/common/lights.glsl.
struct GpuLight {
  glm::vec4 position_radius;  // xyz position, w radius (directional: 0)
  glm::vec4 color_kind;       // rgb colour * intensity, w GpuLightKind
  glm::vec4 direction;        // xyz where the light points (spot, directional)
  glm::vec4 spot;             // x = 1 / (cos inner - cos outer), y = -cos outer * x
  // z: 1 + the index of its first ShadowView when the light is shadowed this
  // frame, else 0 (written by the ShadowAtlas); w: its view count.
  // A point light that moves on the GPU (with_motion) holds its motion where
  // a point light has no use for a direction or a cone: direction = (origin,
  // circle radius), spot.xy = (phase, angular speed); position_radius.xyz is
  // its origin here and where it is this frame in the GPU's copy.
};
static_assert(sizeof(GpuLight) == 64, "must match Light in shaders/common/lights.glsl");

// `light` (a point light) carrying `animation`, for the GPU to move
// (LightAnimationSettings::on_gpu).
[[nodiscard]] GpuLight with_motion(GpuLight light, const LightAnimation& animation);
// Whether `light` carries a motion (with_motion): the C++ twin of
// moves_on_gpu in shaders/light_animation/move_lights.comp.
[[nodiscard]] bool moves_on_gpu(const GpuLight& light);
// Where the GPU places `light` `time` seconds in: its position when it does
// not move (for the few lights the CPU must place, the shadowed ones).
[[nodiscard]] glm::vec3 moved_position(const GpuLight& light, double time);
// How far from its record's position the GPU may place `light` at any time
// (animated_reach; 0 for a light that does not move on the GPU): its sphere
// grown by this much holds it wherever it is, for CPU tests over every light
// that cannot afford moved_position's trigonometry.
[[nodiscard]] float motion_reach(const GpuLight& light);

// The indices of the directional lights among `lights`: volume techniques
// light each in a full-screen pass of its own.
[[nodiscard]] std::vector<std::uint32_t> directional_lights(std::span<const GpuLight> lights);
// How many lights lead `lights` with shadow maps this frame (spot.z set): the
// ShadowAtlas moves the shadowed lights to the front.
[[nodiscard]] std::uint32_t shadowed_light_count(std::span<const GpuLight> lights);

// Lights [begin, end) of the buffer.
struct LightRun {
  std::size_t begin = 0, end = 0;
};

// A light entity that cannot be drawn and why, e.g. "position (nan, 0, 1) is not finite".
struct RejectedLight {
  ecs::Entity entity;
  std::string problem;
};

// Pool slots [first, end) (first == end: none).
struct SlotRange {
  std::uint32_t first = 0, end = 0;
};

// kLightBlock consecutive slots of a chunk's share of the LightColor pool, as
// the walk that last visited them found them: a frame that finds nothing
// written in these slots (nor in the other pools' slots its lights hold) and
// no light added or removed anywhere skips them.
struct LightBlock {
  std::uint32_t drawable = 0;  // lights it put in the buffer
  std::uint32_t rejected = 0;  // light entities it left out
  std::array<SlotRange, 5> slots;  // of its lights' Transform, LightRadius, SpotCone, DirectionalLight, LightAnimation
};

// A share of the LightColor pool, walked by one thread (LightBuffer::chunks).
struct LightChunk {
  std::size_t offset = 0;  // where its lights start in the buffer
  std::size_t count = 0;   // how many of its entities are drawable lights
  std::size_t rejected_count = 0;  // how many are not (walked or skipped)
  std::vector<RejectedLight> rejected;  // those its walked blocks found this frame
  std::vector<LightRun> runs;  // the changed indices it found, in the buffer's numbering
  std::vector<LightBlock> blocks;
};

struct LightBuffer {
  gfx::Buffer buffer;
  std::size_t capacity = 0;  // lights the buffer can hold
  std::uint32_t count = 0;   // lights written this frame
  std::uint32_t uploaded = 0;  // of which sent to the GPU this frame: those that changed
  // What the buffer holds, kept across frames so that a frame sends only the
  // lights that changed (and reuses this memory rather than allocate anew).
  std::vector<GpuLight> staging;
  std::vector<ecs::Entity> entities;  // staging[i] is the light of entities[i]
  std::uint32_t rejected = 0;  // light entities left out this frame
  std::unordered_set<ecs::Entity> warned;  // each rejected entity is warned about once
  std::vector<LightChunk> chunks;  // the gather's shares, kept across frames: where each began
  std::size_t pool_size = 0;       // LightColor components when they were split so
  // Change detection: the change clock the last walk took (0: none yet) and
  // the light pools' structure then (ecs::Registry::structure_version).
  std::uint64_t seen = 0;
  std::array<std::uint64_t, 7> structure{};
  // Indices of the staging copy that a later system changed this frame (the
  // ShadowAtlas moves shadowed lights to the front): the next walk visits
  // them whatever the registry says, to put them back.
  std::vector<std::uint32_t> patched;
  std::uint32_t walked = 0;  // light entities visited this frame; the rest held still
  // Bumped by every write to `buffer` (the walk's uploads, a new buffer, the
  // shadow atlas's patches): a pass that derives records from what was sent
  // (the light motion pass) knows the buffer still holds its result while
  // this and its own inputs are unchanged.
  std::uint64_t sends = 0;
};

struct GatheredLights {
  std::vector<GpuLight> lights;
  std::vector<ecs::Entity> entities;  // per light, its entity
  std::vector<RejectedLight> rejected;
};

// Collects the lights of the registry in GPU layout (radius derived when
// absent). Lights that a system left with a non-finite position or direction,
// or a colour, intensity or radius that is negative, zero where it must not be,
// or not finite, are rejected rather than poisoning every pixel they reach.
[[nodiscard]] GatheredLights gather_lights(ecs::Registry& registry);

void register_light_buffer(ecs::Scheduler& scheduler);

}  // namespace atrium::render
