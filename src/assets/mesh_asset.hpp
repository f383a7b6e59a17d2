// CPU-side mesh data, shaped like glTF: a MeshAsset holds vertex buffers and
// meshes, each mesh holds primitives (one draw each), each primitive indexes one
// vertex buffer and names one material. Primitives that share vertices in the
// file (one accessor set) share one vertex buffer here and on the GPU. glTF
// import and the procedural built-in scene both produce exactly this.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/handles.hpp"
#include "base/box.hpp"

namespace atrium::assets {

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w handedness of the bitangent
  glm::vec2 uv0{0.0f};
  glm::vec2 uv1{0.0f};
  // glTF's COLOR_0 (linear RGBA, 16-bit unorm), which multiplies the base colour.
  std::array<std::uint16_t, 4> color{kWhite, kWhite, kWhite, kWhite};
  static constexpr std::uint16_t kWhite = 65535;
};
static_assert(sizeof(Vertex) == 64, "the GPU vertex layout in gpu_assets.cpp assumes tightly packed 64-byte vertices");

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
  // KHR_materials_unlit: the base colour is the pixel's colour; no light,
  // ambient or emission changes it.
  bool unlit = false;
  // The normal map's green channel points down (DirectX's convention, as in
  // Bistro); glTF's points up.
  bool normal_green_down = false;
  TextureSlot base_color_texture;
  TextureSlot metallic_roughness_texture;
  TextureSlot normal_texture;
  TextureSlot occlusion_texture;
  TextureSlot emissive_texture;

  // The texture slots in shader order (texture units 0-4 of material.glsl).
  static constexpr std::size_t kTextureSlots = 5;
  [[nodiscard]] std::array<const TextureSlot*, kTextureSlots> texture_slots() const {
    return {&base_color_texture, &metallic_roughness_texture, &normal_texture, &occlusion_texture, &emissive_texture};
  }
};

// A run of a primitive's triangles that lie close together (a meshlet, built by
// build_meshlets): a contiguous range of its index list, with the bounds that
// culling tests in object space.
struct Meshlet {
  std::uint32_t first_index = 0;  // into Primitive::indices
  std::uint32_t index_count = 0;
  glm::vec3 center{0.0f};         // a sphere holding every triangle
  float radius = 0.0f;
  // Normal cone: seen from a point p, every triangle faces away when
  // dot(normalize(cone_apex - p), cone_axis) >= cone_cutoff (> 1: never).
  glm::vec3 cone_apex{0.0f};
  glm::vec3 cone_axis{0.0f, 0.0f, 1.0f};
  float cone_cutoff = 2.0f;
};

struct Primitive {
  std::uint32_t vertex_buffer = 0;     // index into MeshAsset::vertex_buffers
  std::vector<std::uint32_t> indices;  // triangle list into that vertex buffer
  std::uint32_t material = 0;          // index into MeshAsset::materials
  glm::vec3 bounds_min{0.0f};          // of the vertices the indices reach
  glm::vec3 bounds_max{0.0f};
  // Empty, or meshlets covering `indices` in order (large opaque primitives).
  std::vector<Meshlet> meshlets;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
};

struct MeshAsset {
  std::string name;
  std::vector<std::vector<Vertex>> vertex_buffers;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;

  [[nodiscard]] const std::vector<Vertex>& vertices(const Primitive& p) const { return vertex_buffers.at(p.vertex_buffer); }
  [[nodiscard]] std::size_t vertex_count() const;
};

// Vertices and indices with no asset yet, as shape builders make them.
struct Geometry {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // triangle list
};

// Moves `geometry` into `asset` as a vertex buffer of its own and returns the
// primitive that draws it with `material`, its bounds computed.
[[nodiscard]] Primitive add_geometry(MeshAsset& asset, Geometry geometry, std::uint32_t material);

// Sets a primitive's bounding box to that of the vertices its indices reach.
void compute_bounds(std::span<const Vertex> vertices, Primitive& primitive);
// Area-weighted smooth normals for every vertex the triangles reach.
void generate_normals(std::span<Vertex> vertices, std::span<const std::uint32_t> indices);
// Per-vertex tangents from UV derivatives (accumulated per triangle, then
// Gram-Schmidt orthogonalised against the normal, with the bitangent sign in w),
// the per-vertex result MikkTSpace also produces for well-formed meshes.
void generate_tangents(std::span<Vertex> vertices, std::span<const std::uint32_t> indices);
inline void generate_normals(Geometry& g) { generate_normals(g.vertices, g.indices); }
inline void generate_tangents(Geometry& g) { generate_tangents(g.vertices, g.indices); }

// Removes triangles with a corner at a NaN or infinite position (or whose
// normal overflows), which would rasterise garbage and poison normals, and
// triangles of zero area (a repeated corner, or three corners on one line),
// which cover no pixel but would give generated normals and tangents a zero
// vector. Real exports have the latter (the teapot's lid has 8).
struct DroppedTriangles {
  std::size_t non_finite = 0, zero_area = 0;
  DroppedTriangles& operator+=(const DroppedTriangles& more) {
    non_finite += more.non_finite;
    zero_area += more.zero_area;
    return *this;
  }
};
DroppedTriangles drop_unusable_triangles(std::span<const Vertex> vertices, std::vector<std::uint32_t>& indices);
// One line per reason that dropped any of a file's `read` triangles: "2 of 40
// triangles have zero area; they are skipped".
[[nodiscard]] std::vector<std::string> dropped_triangle_lines(const DroppedTriangles& dropped, std::size_t read);
// Normalises given normals; where one is zero-length or not finite, uses the
// smooth normal of the triangles instead. Returns whether any was bad.
bool repair_normals(std::span<Vertex> vertices, std::span<const std::uint32_t> triangles);
// Whether every tangent has a usable direction and sign.
[[nodiscard]] bool tangents_valid(std::span<const Vertex> vertices);

[[nodiscard]] std::size_t triangle_count(const Mesh& mesh);

}  // namespace atrium::assets
