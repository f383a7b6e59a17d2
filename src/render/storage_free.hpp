// The compute-free tier (TechniqueOptions::compute_free, --no-compute: no
// compute shaders and no storage buffers, as on WebGL2, OpenGL ES 3.0 and
// OpenGL 4.1): the records the full tier keeps in storage buffers (lights,
// instances, materials) as RGBA32F textures the shaders read with texelFetch
// when compiled with NO_STORAGE_BUFFERS (common/lights.glsl, common/mesh.vert,
// common/material_table.glsl hold the GLSL twins of the layouts below).
// Whole numbers (flags, indices) are stored as float values, exact below 2^24,
// since a texel holding raw integer bits could be a denormal a GPU flushes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/binding_slots.hpp"
#include "gfx/gl.hpp"
#include "gfx/gl_object.hpp"
#include "render/frame/draw_list.hpp"
#include "render/light_buffer.hpp"
#include "render/lighting/cpu_light_lists.hpp"
#include "render/shader_globals.hpp"

namespace atrium::render {

// The NO_STORAGE_BUFFERS row of the shader globals (render/shader_globals.hpp).
void storage_defines(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines);

// Their texture units are in render/binding_slots.hpp.

// Texels per record and records per row, each row within WebGL2's least
// texture width (2,048).
inline constexpr std::uint32_t kLightTexels = 4, kLightsPerRow = 512;
inline constexpr std::uint32_t kInstanceTexels = 9, kInstancesPerRow = 227;
inline constexpr std::uint32_t kMaterialTexels = 14, kMaterialsPerRow = 146;
inline constexpr std::uint32_t kShadowViewTexels = 6, kShadowViewsPerRow = 341;  // common/shadows.glsl
static_assert(sizeof(GpuLight) == kLightTexels * sizeof(glm::vec4), "a light is 4 texels (common/lights.glsl)");
static_assert(sizeof(InstanceData) == kInstanceTexels * sizeof(glm::vec4), "an instance is 9 texels (common/mesh.vert)");
static_assert(sizeof(MaterialData) == kMaterialTexels * sizeof(glm::vec4), "a material is 14 texels (common/material_table.glsl)");

// The texels of each record, in the shaders' order.
[[nodiscard]] std::vector<glm::vec4> instance_texels(std::span<const InstanceData> instances);
// ... of the record each slot names, slot by slot.
[[nodiscard]] std::vector<glm::vec4> instance_texels(std::span<const InstanceData> instances, std::span<const InstanceSlot> slots);
[[nodiscard]] std::vector<glm::vec4> material_texels(std::span<const MaterialData> materials);

// Texels in a record-texture format: the shaders' float records (RGBA32F)
// and the light lists' ranges (RG32UI) and indices (R32UI).
struct TexelFormat {
  GLenum internal_format;
  GLenum pixel_format;
  GLenum type;
  std::size_t bytes;
};
inline constexpr TexelFormat kFloatRecords{GL_RGBA32F, GL_RGBA, GL_FLOAT, sizeof(glm::vec4)};
inline constexpr TexelFormat kLightRanges{GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, sizeof(glm::uvec2)};
inline constexpr TexelFormat kLightIndices{GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, sizeof(std::uint32_t)};

// A texture of records, `texels` texels each, `per_row` a row, grown (never
// shrunk) to hold what it is given.
class RecordTexture {
 public:
  RecordTexture(std::uint32_t texels, std::uint32_t per_row, TexelFormat format = kFloatRecords)
      : texels_(texels), per_row_(per_row), format_(format) {}
  // `records` whole records, `format.bytes` a texel.
  void upload(const void* data, std::size_t records);
  void upload(std::span<const glm::vec4> texels) { upload(texels.data(), texels.size() / texels_); }
  void bind(GLuint unit) const;

 private:
  std::uint32_t texels_, per_row_;
  TexelFormat format_;
  gfx::Texture texture_;
  int rows_ = 0;
};

// Light lists built on the CPU (render/lighting/cpu_light_lists.hpp) as the
// tier's shaders read them (common/light_lists.glsl): per bin its range
// (RG32UI), then the light indices (R32UI), kListTextureWidth texels a row.
inline constexpr std::uint32_t kListTextureWidth = 2048;

class ListTextures {
 public:
  void upload(const lighting::CpuLightLists& lists);
  void bind() const;
  // The entries of the lists last uploaded.
  [[nodiscard]] std::uint32_t entries() const { return entries_; }

 private:
  RecordTexture ranges_{1, kListTextureWidth, kLightRanges};
  RecordTexture indices_{1, kListTextureWidth, kLightIndices};
  std::uint32_t entries_ = 0;
};

// The frame's records as textures, bound for every pass of the frame.
class StorageFreeRecords {
 public:
  void upload(std::span<const GpuLight> lights, const DrawList& draws);
  void bind() const;

 private:
  RecordTexture lights_{kLightTexels, kLightsPerRow};
  RecordTexture instances_{kInstanceTexels, kInstancesPerRow};
  RecordTexture materials_{kMaterialTexels, kMaterialsPerRow};
};

}  // namespace atrium::render
