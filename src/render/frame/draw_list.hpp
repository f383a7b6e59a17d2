// The frame's visible geometry as indirect draw batches, gathered from the
// MeshInstance entities the culling systems marked visible (once, and again
// after the first pass when occlusion culling revealed more) and shared by
// every pass of every technique. Per-instance data (model matrix, material
// index) and material parameters live in storage buffers, so one
// glMultiDrawElementsIndirect draws every primitive that shares a vertex
// layout, a texture set and a cull state: the number of draws follows the
// scene's distinct texture sets, not its objects.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/binding_slots.hpp"
#include "assets/asset_manager.hpp"
#include "render/gpu_assets.hpp"
#include "ecs/registry.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_program.hpp"
#include "render/frame_graph.hpp"

namespace atrium::render {

// Texture units 0-4: base colour, metallic-roughness, normal, occlusion, emissive.
inline constexpr unsigned kMaterialTextureSlots = assets::Material::kTextureSlots;

// std430 twin of Instance in shaders/common/mesh.vert: one primitive instance's record.
struct InstanceData {
  glm::mat4 model{1.0f};
  glm::mat4 normal_matrix{1.0f};  // inverse transpose of the model's 3x3, in a mat4 to keep std430 simple
  // x: index into DrawList::materials; y: the visibility identifier of the
  // primitive's first triangle (VisibilityUnit::first_id); z, w: its first
  // index and base vertex in the GPU's pools (GpuPrimitive).
  glm::uvec4 material{0};
};
static_assert(sizeof(InstanceData) == 144, "must match Instance in shaders/common/mesh.vert");

// One instance a command draws: the value of the instance-slot attribute
// (kInstanceSlotLocation, a_instance in shaders/common/mesh.vert), read at
// the command's base instance plus the instance's index. The meshlets of one
// primitive instance are commands of their own that share its record, so a
// list of one command per meshlet carries 8 bytes a command, not a record.
struct InstanceSlot {
  std::uint32_t record = 0;          // into DrawList::instances
  std::uint32_t first_triangle = 0;  // where the command's triangles start in the primitive (visibility identifiers)
};
static_assert(sizeof(InstanceSlot) == kInstanceSlotBytes, "two 32-bit components of the instance-slot attribute (common/mesh.vert)");

// std430 twin of Unit in shaders/visibility/visibility.glsl. Every triangle of
// the scene has a 32-bit identifier for the frame, stable through occlusion
// culling's phases (whatever list drew it): its primitive instance's first
// identifier (units in registry order, from 1; 0 is no geometry) plus its index
// in the primitive. The visibility buffer stores it; its resolve finds the
// unit by binary search and the unit's record in the frame's instances.
struct VisibilityUnit {
  static constexpr std::uint32_t kNotDrawn = 0xffffffffu;
  std::uint32_t first_id = 0;
  std::uint32_t record = kNotDrawn;  // its record in the list's instances, if an opaque command draws it
};
static_assert(sizeof(VisibilityUnit) == 8, "must match Unit in shaders/visibility/visibility.glsl");
// The head of the Units block: how many units follow it. The binary search
// takes its end from this count, not from the block's length(): GL derives
// that from the range bound, but Mesa's zink gave the whole buffer's, and the
// search ran into stale units (the bound resolve shaded one material of many).
struct VisibilityUnitsHead {
  std::uint32_t count = 0;
  std::uint32_t unused = 0;  // the units start 8 bytes in
};
static_assert(sizeof(VisibilityUnitsHead) == 8, "must match the head of Units in shaders/visibility/visibility.glsl");
// The graph's name for the target of those identifiers (R32UI), which the
// visibility buffer writes and its debug views read.
inline constexpr char kVisibilityIdsTarget[] = "visibility-ids";

// Material::flags bits; GLSL twins in shaders/common/material_data.glsl.
inline constexpr std::uint32_t kMaterialHasNormalTexture = 1u << 0;
inline constexpr std::uint32_t kMaterialNormalXyOnly = 1u << 1;     // a two-channel (BC5) normal map: z is rebuilt
inline constexpr std::uint32_t kMaterialNormalGreenDown = 1u << 2;  // DirectX's convention: green points down
inline constexpr std::uint32_t kMaterialDoubleSided = 1u << 3;
inline constexpr std::uint32_t kMaterialUnlit = 1u << 4;            // KHR_materials_unlit
inline constexpr std::uint32_t kMaterialAlphaMasked = 1u << 5;

// std430 twin of Material in shaders/common/material_data.glsl.
struct MaterialData {
  glm::vec4 base_color_factor{1.0f};
  glm::vec4 emissive{0.0f};  // rgb: emissive factor times strength; a: normal scale
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;
  float occlusion_strength = 0.0f;  // 0 without an occlusion texture
  float alpha_cutoff = -1.0f;       // < 0 when the material is not alpha-masked
  std::uint32_t flags = 0;          // kMaterial* bits
  std::uint32_t uv_sets = 0;        // bit s: texture slot s reads UV set 1
  std::uint32_t padding[2] = {0, 0};
  // Per texture slot, the two rows of its KHR_texture_transform (a 2x3 affine map).
  std::array<glm::vec4, 2 * kMaterialTextureSlots> uv_transform{};
};
static_assert(sizeof(MaterialData) == 224, "must match Material in shaders/common/material_data.glsl");

[[nodiscard]] MaterialData material_data(const assets::Material& material, const GpuAssets& gpu);

// GL's DrawElementsIndirectCommand.
struct DrawCommand {
  std::uint32_t count = 0;
  std::uint32_t instance_count = 0;
  std::uint32_t first_index = 0;
  std::int32_t base_vertex = 0;
  std::uint32_t base_instance = 0;
};
static_assert(sizeof(DrawCommand) == 20, "GL reads indirect commands as five 32-bit words");

// std430 twin of CullRecord in shaders/culling/occlusion_cull.comp: what GPU
// occlusion culling tests for one opaque command of a DrawSelection::EachInView
// list (one primitive or meshlet of one instance).
struct CullRecord {
  static constexpr std::uint32_t kNeverCulled = 0xffffffffu;  // an entity without bounds: always drawn
  glm::vec4 box_min{0.0f};  // world space; w unused
  glm::vec4 box_max{0.0f};
  std::uint32_t unit = kNeverCulled;  // its slot in the GPU's shown-last-frame bits, stable while the scene's entities are
  std::uint32_t triangles = 0;
  std::uint32_t padding[2] = {0, 0};
};
static_assert(sizeof(CullRecord) == 48, "must match CullRecord in shaders/culling/occlusion_cull.comp");

// One glMultiDrawElementsIndirect: commands sharing a vertex array, the five
// material textures and samplers, and a cull state.
struct DrawBatch {
  GLuint vertex_array = 0;
  std::array<GLuint, kMaterialTextureSlots> textures{};
  std::array<GLuint, kMaterialTextureSlots> samplers{};
  bool double_sided = false;
  // The instances' transforms mirror (negative determinant): glTF then takes
  // clockwise triangles as front faces.
  bool mirrored = false;
  // Alpha-masked: fragments below the cutoff are discarded, so even a depth-only
  // pass must evaluate the material's alpha.
  bool alpha_masked = false;
  std::uint32_t first_command = 0;  // into DrawList::commands
  std::uint32_t command_count = 0;
  // Its draw count's slot in a parameter buffer (CommandSource::count_base): opaque
  // batches first, then blended, in list order.
  std::uint32_t count_slot = 0;
};

// The state a batch of `material`'s primitives draws with (no commands yet).
[[nodiscard]] DrawBatch batch_state(const assets::Material& material, const GpuAssets& gpu, GLuint vertex_array, bool mirrored);

struct DrawList {
  // Opaque and alpha-masked geometry: ordered by state (masked last, then
  // vertex array and textures), commands front to back within a batch,
  // identical primitives instanced.
  std::vector<DrawBatch> opaque;
  // Blended geometry, one command per primitive instance, farthest first;
  // neighbours with the same state share a batch (draw order is kept).
  std::vector<DrawBatch> blended;
  std::vector<DrawCommand> commands;
  std::vector<float> command_depths;  // per command: view depth of its nearest instance's primitive centre
  // One record per primitive instance drawn, and what each command's
  // instances draw with (DrawCommand::base_instance indexes the slots).
  std::vector<InstanceData> instances;
  std::vector<InstanceSlot> slots;
  std::vector<MaterialData> materials;
  // DrawSelection::EachInView only: one record per opaque command (commands
  // [0, cull_records.size())), and how many units the scene has in all.
  std::vector<CullRecord> cull_records;
  std::uint32_t cull_units = 0;
  // Every primitive instance of the scene, in view or not, in registry order
  // (InstanceData::material.y); the identifiers they use run to
  // visibility_ids (more than 2^32 cannot be told apart: the visibility buffer refuses).
  std::vector<VisibilityUnit> visibility_units;
  std::uint64_t visibility_ids = 1;
  std::size_t triangles = 0;        // in the scene, every instance, visible or not
  std::size_t triangles_drawn = 0;  // by one pass over opaque and blended: what culling kept

  [[nodiscard]] std::size_t draw_calls() const { return opaque.size() + blended.size(); }
};

// Which of the geometry in view a list holds: occlusion culling's phases
// (render/culling/occlusion_culling.hpp, the seen:: bits of components/visibility.hpp).
enum class DrawSelection {
  InView,          // all of it (occlusion culling off)
  ShownLastFrame,  // what the first pass draws before testing the rest
  Revealed,        // what it draws after (opaque geometry only)
  Shown,           // both: what the passes after the first draw
  EachInView,      // all of it, one command per primitive or meshlet with its box (CullRecord): the GPU culls
};
// Whether a primitive or meshlet in `state` (seen:: bits) belongs to `selection`.
[[nodiscard]] bool selected(std::uint8_t state, DrawSelection selection);

// Builds the frame's list from the entities' WorldBounds and Visibility (an
// entity without them is drawn whole). `view` orders draws by distance.
// Blended surfaces in view are in every selection but Revealed: they are not
// occlusion-culled.
[[nodiscard]] DrawList build_draw_list(ecs::Registry& registry, const assets::AssetManager& assets,
                                       const GpuAssets& gpu, const glm::mat4& view,
                                       DrawSelection selection = DrawSelection::InView);

// Where draw_items takes a list's commands, kept with the buffers that hold
// them by whoever binds those (render::FrameDraws, the shadow atlas).
struct CommandSource {
  // Empty: the bound GL_DRAW_INDIRECT_BUFFER. Else, on the compute-free tier
  // (no indirect draws or base instances on WebGL2 and OpenGL ES 3.0), these
  // CPU copies, one draw each, the first instance given as the constant value
  // of the instance-slot attribute (common/mesh.vert adds gl_InstanceID; the
  // tier's records are laid out slot by slot, StorageFreeRecords).
  std::span<const DrawCommand> cpu_commands;
  // GPU occlusion culling where GL 4.6 or ARB_indirect_parameters has
  // glMultiDrawElementsIndirectCount: each batch draws the first commands of
  // its range, as many as the bound GL_PARAMETER_BUFFER holds at
  // `count_base + 4 * count_slot` bytes. Negative: every command.
  GLintptr count_base = -1;
};

// Issues one multi-draw per batch with the program in use, binding each batch's
// textures to units 0-4, disabling back-face culling for double-sided batches
// and turning the front face for mirrored ones. The instance and material
// buffers and `source`'s indirect buffer must be bound (FrameDraws::bind binds
// the frame's). Leaves culling enabled and counter-clockwise front faces on return.
void draw_items(std::span<const DrawBatch> batches, const CommandSource& source);

// Depth only, for pre-passes: batches without an alpha test through
// `position_only` (common/mesh.vert with POSITION_ONLY and common/depth_only.frag:
// no varyings, no material reads), alpha-masked ones through `masked`, which
// discards below the cutoff. Colour writes are the caller's to disable.
void draw_depth(std::span<const DrawBatch> batches, const CommandSource& source, gfx::ShaderProgram& position_only,
                gfx::ShaderProgram& masked);

struct FrameContext;
struct FrameTargets;

// Draws the frame's blended items over the lit image, back to front, shaded by
// every light with `forward_program`, depth-tested against the opaque depth
// (the body of the "transparency" pass, frame/scene_passes.hpp).
void draw_transparent(const PassResources& res, gfx::ShaderProgram& forward_program, const FrameContext& frame,
                      const FrameTargets& targets);

// Binds the HDR target, clears it to the background and depth to the far
// plane (gfx::kDepthFar, reversed depth), and sets
// the state for drawing scene geometry (depth test kDepthCloser with writes, no blend).
void begin_scene_pass(const PassResources& res, const FrameContext& frame, const FrameTargets& targets);
// Clears the bound `framebuffer`'s depth-stencil to the far plane and sets
// that state (what begin_scene_pass does after clearing colour).
void begin_depth(GLuint framebuffer);

// A triangle that covers the viewport, for full-screen passes.
class FullscreenTriangle {
 public:
  FullscreenTriangle() : vertex_array_(gfx::create_vertex_array()) {}
  void draw() const;

 private:
  gfx::VertexArray vertex_array_;
};

}  // namespace atrium::render
