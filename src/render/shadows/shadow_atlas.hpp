// Shadow maps for many lights (--shadows K). Reads the frame's lights, the
// camera and every opaque or alpha-masked primitive; writes one depth texture,
// the atlas, holding the maps of the K lights that matter most this frame
// (shadow_selection.hpp), their ShadowView records, and each shadowed light's
// spot.zw in the light buffer. It runs before the lighting technique, so every
// mode samples the same maps through shaders/common/shadows.glsl. A map is drawn
// again only when its light, its tile or the geometry within its reach changed.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "render/binding_slots.hpp"
#include "render/shader_globals.hpp"
#include "assets/asset_manager.hpp"
#include "render/gpu_assets.hpp"
#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "ecs/registry.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/stream_buffer.hpp"
#include "render/light_buffer.hpp"
#include "render/frame/draw_list.hpp"
#include "render/shadows/atlas_allocator.hpp"
#include "render/shadows/shadow_selection.hpp"
#include "render/shadows/shadow_views.hpp"
#include "render/storage_free.hpp"

namespace atrium::shadows {

// Where the shaders find the atlas (a sampler2DShadow) and the views (std430).
using render::kShadowViewBinding;
// The atlas's side, or the context's largest texture if that is smaller.
inline constexpr int kAtlasSize = 4096;
// Depth bias while drawing maps: the slope-scaled term grows with how steeply a
// surface is seen from the light, the constant one covers depth rounding.
// Sampling adds a normal offset of a texel or so (shaders/common/shadows.glsl).
inline constexpr float kSlopeBias = 2.0f;
inline constexpr float kConstantBias = 1.0f;

struct ShadowStats {
  std::uint32_t lights = 0;         // shadowed this frame
  std::uint32_t maps_rendered = 0;  // views (cube faces, cones, cascades) drawn this frame
  std::uint32_t maps_reused = 0;    // views kept from an earlier frame
  std::size_t triangles = 0;        // submitted by this frame's shadow passes
  int atlas_size = 0;               // texels per side; 0 while shadows are off
};

class ShadowAtlas {
 public:
  static constexpr GLenum kAtlasFormat = GL_DEPTH_COMPONENT32F;

  // The SHADOWS row of the shader globals (render/shader_globals.hpp): the
  // lookup in every light loop (common/shadows.glsl) while lights have maps.
  static void shadow_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.settings.shadows > 0) defines.push_back({"SHADOWS"});
  }

  explicit ShadowAtlas(render::GpuAssets& gpu);
  // The compute-free tier (render/storage_free.hpp): views, caster instances
  // and materials in textures, casters drawn from the CPU's commands.
  void set_compute_free(bool on) { compute_free_ = on; }

  // Chooses this frame's maps, moves the shadowed lights to the front of
  // `lights` and patches them (CPU copy and buffer; light loops rely on the
  // order, common/shading.glsl), binds the atlas and the views for the frame's
  // shaders. Returns whether some maps must be drawn: draw_pending, the
  // frame's "shadows" pass. `count` 0 gives everything back; `redraw` draws
  // every map, changed or not (to measure the worst case).
  [[nodiscard]] bool update(ecs::Registry& registry, render::LightBuffer& lights, const ViewState& view, glm::ivec2 viewport, int count,
                            bool redraw);
  // Draws the maps update() found stale, with instance, material and command
  // buffers of its own (bound when it returns), then binds the atlas again.
  void draw_pending(ecs::Registry& registry);
  // Whether update() left maps for draw_pending.
  [[nodiscard]] bool has_pending() const { return !pending_views_.empty(); }

  // The atlas texture (depth, compare mode on), 0 while shadows are off.
  [[nodiscard]] GLuint texture() const { return atlas_.id(); }
  [[nodiscard]] const ShadowStats& stats() const { return stats_; }
  // This frame's views, in the order the shadowed lights' spot.z points into.
  [[nodiscard]] std::span<const ShadowView> views() const { return views_; }

 private:
  // A shadowed light's tiles and what its maps were drawn from.
  struct Entry {
    int resolution = 0;
    std::vector<AtlasTile> tiles;
    render::GpuLight drawn_light{};                 // the light as its maps show it
    std::vector<glm::mat4> drawn_views;     // the matrices they were drawn with
    bool drawn = false;
  };
  // One opaque or alpha-masked primitive of one instance, as a shadow caster.
  struct Caster {
    Box box;
    std::uint32_t state = 0;  // index into caster_states_ (masked states sort last)
    render::DrawCommand command;
    // Its meshlets (world bounds, index ranges within the primitive), when it
    // is cut into them: a view then draws only the runs inside it.
    const MeshletBounds* meshlet_bounds = nullptr;
    const assets::Meshlet* meshlets = nullptr;
    std::uint32_t meshlet_count = 0;
    // An emissive surface: no shadow for a light inside its box (the light's
    // own lamp glass), a shadow for every other light.
    bool glows = false;
  };

  void release();
  void ensure_atlas();
  // Boxes of geometry that appeared, moved or went away since the last frame.
  void collect_changed_geometry(ecs::Registry& registry);
  void gather_casters(ecs::Registry& registry);
  // Draws `views` (indices into views_), each from the casters inside its
  // frustum and its light's sphere (reach: xyz centre, w radius; w < 0: unbounded).
  void draw_maps(const std::vector<std::uint32_t>& views, std::span<const glm::vec4> reach);
  void bind() const;

  render::GpuAssets& gpu_;
  AtlasLimits limits_;
  AtlasAllocator allocator_;
  gfx::Texture atlas_;
  gfx::Framebuffer framebuffer_;
  gfx::StreamBuffer view_buffer_, instances_, materials_, commands_;
  bool compute_free_ = false;
  render::RecordTexture view_texture_{render::kShadowViewTexels, render::kShadowViewsPerRow};
  render::RecordTexture instance_texture_{render::kInstanceTexels, render::kInstancesPerRow};
  render::RecordTexture material_texture_{render::kMaterialTexels, render::kMaterialsPerRow};
  std::unordered_map<ecs::Entity, Entry> entries_;
  std::vector<ShadowView> views_;
  // The views update() found stale and their lights' spheres, for draw_pending.
  std::vector<std::uint32_t> pending_views_;
  std::vector<glm::vec4> pending_reach_;
  // Geometry tracking: each instance's world box last frame, and this frame's changes.
  struct Seen {
    Box box;
    std::uint64_t frame = 0;
  };
  std::unordered_map<ecs::Entity, Seen> boxes_;
  std::vector<Box> changed_;
  std::uint64_t frame_ = 0;
  // The frame's casters (gathered only on frames that draw a map).
  std::vector<Caster> casters_;
  std::vector<render::DrawBatch> caster_states_;
  std::vector<render::InstanceData> caster_instances_;
  std::vector<render::MaterialData> caster_materials_;
  ShadowStats stats_;
};

}  // namespace atrium::shadows
