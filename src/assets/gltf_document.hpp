// A glTF 2.0 file (.gltf or .glb) as checked data: the JSON read with
// nlohmann_json, every buffer loaded (GLB chunk, external file, data URI, or
// none for an EXT_meshopt_compression fallback), and every index, count,
// offset and stride the file declares checked against what it refers to before
// anything is allocated for it. gltf_import.cpp turns a document into meshes.
// Why not tinygltf: Debian's 2.7 refuses the data-less fallback buffers that
// gltfpack and glTF-Transform write and the accessors of Draco primitives.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include "assets/json_reader.hpp"
#include "assets/load_budget.hpp"

namespace atrium::assets {


namespace gltf {

// The JSON pointer of element `i` of a top-level array: element("meshes", 0)
// is /meshes/0. Messages name glTF objects this way, as gltf-validator does.
[[nodiscard]] inline JsonPointer element(std::string_view array, std::size_t i) { return JsonPointer() / array / i; }

// glTF's componentType codes (GL's).
enum ComponentType : int {
  kByte = 5120,
  kUnsignedByte = 5121,
  kShort = 5122,
  kUnsignedShort = 5123,
  kUnsignedInt = 5125,
  kFloat = 5126,
};
[[nodiscard]] std::size_t component_size(int component_type);

struct Buffer {
  std::vector<std::uint8_t> data;
  std::size_t byte_length = 0;
  // EXT_meshopt_compression's fallback: a buffer with no data that only
  // compressed bufferViews point into (their data is decoded elsewhere).
  bool fallback_only = false;
};

struct MeshoptSource {
  std::size_t buffer = 0, byte_offset = 0, byte_length = 0, byte_stride = 0, count = 0;
  enum class Mode { Attributes, Triangles, Indices } mode = Mode::Attributes;
  enum class Filter { None, Octahedral, Quaternion, Exponential } filter = Filter::None;
};

struct BufferView {
  std::size_t buffer = 0;
  std::size_t byte_offset = 0;
  std::size_t byte_length = 0;
  std::size_t byte_stride = 0;  // 0: elements are tightly packed
  std::optional<MeshoptSource> meshopt;
};

struct Accessor {
  int buffer_view = -1;  // -1: zeros (then sparse), or data decoded from a Draco stream
  std::size_t byte_offset = 0;
  int component_type = kFloat;
  int components = 1;  // SCALAR 1, VEC2 2, VEC3 3, VEC4 4, MAT2 4, MAT3 9, MAT4 16
  std::string type = "SCALAR";
  bool normalized = false;
  std::size_t count = 0;
  struct Sparse {
    std::size_t count = 0;
    std::size_t indices_view = 0, indices_offset = 0;
    int indices_component_type = kUnsignedInt;
    std::size_t values_view = 0, values_offset = 0;
  };
  std::optional<Sparse> sparse;

  [[nodiscard]] std::size_t element_size() const { return component_size(component_type) * static_cast<std::size_t>(components); }
};

struct DracoPrimitive {
  std::size_t buffer_view = 0;
  std::map<std::string, int> attributes;  // glTF semantic -> Draco attribute id
};

struct Primitive {
  std::map<std::string, int> attributes;  // semantic -> accessor
  int indices = -1;
  int material = -1;
  int mode = 4;  // TRIANGLES
  std::optional<DracoPrimitive> draco;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
};

struct TextureInfo {
  int index = -1;
  int tex_coord = 0;
  double scale = 1.0;  // normalTexture.scale or occlusionTexture.strength
  Json extensions = Json::object();
};

struct Material {
  std::string name;
  std::array<double, 4> base_color_factor{1.0, 1.0, 1.0, 1.0};
  double metallic_factor = 1.0;
  double roughness_factor = 1.0;
  std::array<double, 3> emissive_factor{0.0, 0.0, 0.0};
  std::string alpha_mode = "OPAQUE";
  double alpha_cutoff = 0.5;
  bool double_sided = false;
  TextureInfo base_color, metallic_roughness, normal, occlusion, emissive;
  Json extensions = Json::object();
};

struct Texture {
  int sampler = -1;
  int source = -1;
  int dds_source = -1;  // MSFT_texture_dds: the DDS image preferred over `source`
  Json extensions = Json::object();
};

struct Image {
  std::string name;
  std::string uri;  // empty when the image lives in a bufferView
  int buffer_view = -1;
  std::string mime_type;
};

struct Sampler {
  int mag_filter = -1, min_filter = -1;
  int wrap_s = 10497, wrap_t = 10497;
};

struct Node {
  std::string name;
  int mesh = -1;
  std::vector<int> children;
  glm::mat4 local{1.0f};  // matrix, or translation * rotation * scale
  int light = -1;         // KHR_lights_punctual
  // EXT_mesh_gpu_instancing: accessors of per-instance TRS (-1 when absent).
  struct Instancing {
    int translation = -1, rotation = -1, scale = -1;
  };
  std::optional<Instancing> instancing;
};

struct Light {
  std::string name;
  std::string type;
  std::array<double, 3> color{1.0, 1.0, 1.0};
  double intensity = 1.0;
  double range = 0.0;  // 0: unlimited
  double inner_cone = 0.0, outer_cone = 0.7853981633974483;
};

struct Document {
  std::filesystem::path path;
  std::vector<Buffer> buffers;
  std::vector<BufferView> buffer_views;
  std::vector<Accessor> accessors;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Image> images;
  std::vector<Sampler> samplers;
  std::vector<Node> nodes;
  std::vector<std::vector<int>> scenes;  // root nodes of each scene
  int scene = -1;                        // the default scene
  std::vector<Light> lights;
  std::vector<std::string> extensions_used, extensions_required;
  std::vector<std::string> warnings;  // each names the file
};

// Reads and checks the whole file. Throws ImportError naming the file, the
// object (`/accessors/3/count`) and the numbers.
[[nodiscard]] Document read_document(const std::filesystem::path& path, const MemoryBudget& budget);

// The bytes of an image file next to the glTF, found from a URI (relative,
// percent-encoded) or decoded from a data URI; empty with `error` set when
// neither works.
[[nodiscard]] std::vector<std::uint8_t> read_image_uri(const Document& document, const std::string& uri,
                                                       const MemoryBudget& budget, std::string& error);

// Why an image URI cannot be read (empty when it can), without reading it.
[[nodiscard]] std::string image_uri_problem(const Document& document, const std::string& uri);


}  // namespace gltf
}  // namespace atrium::assets
