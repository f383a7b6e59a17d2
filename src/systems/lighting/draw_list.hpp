// The frame's geometry as draw items, gathered once from MeshInstance entities
// and shared by every pass of every technique: opaque and alpha-masked items,
// one instanced draw per primitive and material however many entities show it,
// in the order they are first met; blended items one per instance, sorted back
// to front. Each instance's transforms sit in the frame's instance buffer.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "assets/asset_manager.hpp"
#include "assets/gpu_assets.hpp"
#include "ecs/registry.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::lighting {

// Texture units 0-4: base colour, metallic-roughness, normal, occlusion, emissive.
inline constexpr unsigned kMaterialTextureSlots = 5;

// Where mesh.vert finds the instance records (a storage buffer binding).
inline constexpr unsigned kInstanceStorageBinding = 1;

// std430 twin of Instance in shaders/common/mesh.vert: one drawn instance.
struct InstanceData {
  glm::mat4 model{1.0f};
  glm::mat4 normal_matrix{1.0f};  // inverse transpose of the model's 3x3, in a mat4 to keep std430 simple
};
static_assert(sizeof(InstanceData) == 128, "must match Instance in shaders/common/mesh.vert");

struct DrawItem {
  GLuint vertex_array = 0;
  assets::GpuPrimitive range;
  const assets::Material* material = nullptr;
  std::uint32_t first_instance = 0;  // into DrawList::instances
  std::uint32_t instance_count = 1;
  // The instances' transforms mirror (negative determinant): glTF then takes
  // clockwise triangles as front faces.
  bool mirrored = false;
  float view_depth = 0.0f;  // blended items: distance along the view axis to the bounds' centre
};

struct DrawList {
  std::vector<DrawItem> opaque;   // Opaque and Mask materials, instanced
  std::vector<DrawItem> blended;  // Blend materials, one per instance, farthest first
  std::vector<InstanceData> instances;
  std::size_t triangles = 0;      // over every instance
};

[[nodiscard]] DrawList build_draw_list(ecs::Registry& registry, const assets::AssetManager& assets,
                                       const assets::GpuAssets& gpu, const glm::mat4& view);

// Issues one instanced draw per item with `program`: sets the material
// uniforms, binds the material's textures to units 0-4, disables back-face
// culling for double-sided materials and turns the front face for mirrored
// items. The frame's instance buffer must be bound at kInstanceStorageBinding.
// Leaves culling enabled and counter-clockwise front faces on return.
void draw_items(gfx::ShaderProgram& program, const assets::GpuAssets& gpu, std::span<const DrawItem> items);

struct FrameContext;
struct FrameTargets;

// Draws the frame's blended items over the lit image, back to front, shaded by
// every light with `forward_program`, depth-tested against the opaque depth.
void draw_transparent(gfx::ShaderProgram& forward_program, const FrameContext& frame, const FrameTargets& targets);

// Binds the HDR target, clears it to the background and depth to 1, and sets
// the state for drawing scene geometry (depth test LESS with writes, no blend).
void begin_scene_pass(const FrameContext& frame, const FrameTargets& targets);

// A triangle that covers the viewport, for full-screen passes.
class FullscreenTriangle {
 public:
  FullscreenTriangle() : vertex_array_(gfx::create_vertex_array()) {}
  void draw() const;

 private:
  gfx::VertexArray vertex_array_;
};

}  // namespace atrium::lighting
