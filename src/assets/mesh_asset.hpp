// CPU-side mesh data, shaped like glTF: a MeshAsset holds meshes, each mesh holds
// primitives (one draw call each), each primitive names one material. glTF import
// and the procedural built-in scene both produce exactly this.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/handles.hpp"

namespace atrium::assets {

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w handedness of the bitangent
  glm::vec2 uv0{0.0f};
  glm::vec2 uv1{0.0f};
};
static_assert(sizeof(Vertex) == 56, "the GPU vertex layout in gpu_assets.cpp assumes tightly packed 56-byte vertices");

enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// Texture filtering and wrapping, with glTF's numeric codes (which are GL's).
struct SamplerDesc {
  static constexpr std::uint16_t kNearest = 9728, kLinear = 9729, kLinearMipmapLinear = 9987;
  static constexpr std::uint16_t kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648;
  std::uint16_t mag_filter = kLinear;
  std::uint16_t min_filter = kLinearMipmapLinear;
  std::uint16_t wrap_s = kRepeat;
  std::uint16_t wrap_t = kRepeat;
  auto operator<=>(const SamplerDesc&) const = default;
};

// One texture a material samples: which image, how, with which UV set, and the
// KHR_texture_transform matrix applied to the UVs (identity when absent).
struct TextureSlot {
  TextureHandle texture;
  SamplerDesc sampler;
  std::uint8_t uv_set = 0;
  glm::mat3 uv_transform{1.0f};

  [[nodiscard]] bool valid() const { return texture.valid(); }
};

// glTF 2.0 metallic-roughness material. Texture channels follow glTF:
// metallic_roughness.g = roughness, .b = metallic; occlusion.r.
struct Material {
  std::string name;
  glm::vec4 base_color_factor{1.0f};
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;
  glm::vec3 emissive_factor{0.0f};
  float emissive_strength = 1.0f;
  float normal_scale = 1.0f;
  float occlusion_strength = 1.0f;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
  TextureSlot base_color_texture;
  TextureSlot metallic_roughness_texture;
  TextureSlot normal_texture;
  TextureSlot occlusion_texture;
  TextureSlot emissive_texture;
};

struct Primitive {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // triangle list
  std::uint32_t material = 0;          // index into MeshAsset::materials
  glm::vec3 bounds_min{0.0f};
  glm::vec3 bounds_max{0.0f};
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
};

struct MeshAsset {
  std::string name;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
};

// Recomputes a primitive's bounding box from its vertices.
void compute_bounds(Primitive& primitive);
// Area-weighted smooth vertex normals.
void generate_normals(Primitive& primitive);
// Per-vertex tangents from UV derivatives (accumulated per triangle, then
// Gram-Schmidt orthogonalised against the normal, with the bitangent sign in w),
// the per-vertex result MikkTSpace also produces for well-formed meshes.
void generate_tangents(Primitive& primitive);

[[nodiscard]] std::size_t triangle_count(const Mesh& mesh);

}  // namespace atrium::assets
