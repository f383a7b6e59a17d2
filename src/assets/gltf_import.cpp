#include "assets/gltf_import.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "assets/gltf_compression.hpp"
#include "assets/gltf_extensions.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using gltf::Accessor;


std::string accessor_name(int index) { return gltf::element("accessors", static_cast<std::size_t>(index)).str(); }

float to_float(const std::uint8_t* p, int type, bool normalized) {
  switch (type) {
    case gltf::kByte: {
      const auto v = static_cast<std::int8_t>(*p);
      return normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
    }
    case gltf::kUnsignedByte: return normalized ? *p / 255.0f : static_cast<float>(*p);
    case gltf::kShort: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
    }
    case gltf::kUnsignedShort: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0f : static_cast<float>(v);
    }
    case gltf::kUnsignedInt: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? static_cast<float>(v / 4294967295.0) : static_cast<float>(v);
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

std::uint32_t to_index(const std::uint8_t* p, int type) {
  switch (type) {
    case gltf::kUnsignedByte: return *p;
    case gltf::kUnsignedShort: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

std::uint16_t to_unorm16(float v) { return static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f)); }

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The accessors a primitive's vertices come from: primitives with the same set
// share one vertex buffer.
struct VertexSource {
  int position = -1, normal = -1, tangent = -1, uv0 = -1, uv1 = -1, color = -1;
  auto operator<=>(const VertexSource&) const = default;
};

class Importer {
 public:
  Importer(const fs::path& path, AssetManager& assets, const ImportOptions& options)
      : path_(path), name_(path.string()), assets_(assets), progress_(options.progress), threads_(options.decode_threads),
        budget_(options.memory_limit) {
    budget_.set_file(name_);
  }

  ModelImport run() {
    const auto start = Clock::now();
    doc_ = gltf::read_document(path_, budget_);
    result_.warnings = std::move(doc_.warnings);
    check_extensions();
    decode_compressed_views();
    MeshAsset asset;
    asset.name = path_.filename().string();
    asset.materials = read_materials();
    for (std::size_t m = 0; m < doc_.meshes.size(); ++m) asset.meshes.push_back(read_mesh(m, asset));
    finish_vertex_buffers(asset);
    warn_skipped(non_finite_, "have NaN or infinite positions");
    warn_skipped(zero_area_, "have zero area");
    result_.timings.parse_seconds = seconds_since(start);
    const auto decode_start = Clock::now();
    decode_images(asset.materials);
    result_.timings.decode_seconds = seconds_since(decode_start);
    place_nodes(asset);
    result_.asset = assets_.add_mesh_asset(std::move(asset), fs::weakly_canonical(path_).string());
    return std::move(result_);
  }

 private:
  // Things left out (triangles, instances), counted over the places they
  // come from, for one warning per reason.
  struct Skipped {
    std::size_t count = 0, places = 0;
    std::string first;  // "/meshes/3/primitives/0"
    void add(std::size_t n, const std::string& place) {
      if (n == 0) return;
      if (places++ == 0) first = place;
      count += n;
    }
    [[nodiscard]] std::string where(const char* kind) const {
      return places > 1 ? first + " and " + std::to_string(places - 1) + " more " + kind : first;
    }
  };

  // What finish_vertex_buffers needs to know about each vertex buffer.
  struct BufferState {
    bool given_normals = false, given_tangents = false;
    std::vector<std::uint32_t> triangles;  // every primitive's indices into it
    std::string first_user;
  };

  [[noreturn]] void fail(const std::string& problem) const { throw ImportError(name_ + ": " + problem); }
  void warn(const std::string& problem) { result_.warnings.push_back(name_ + ": " + problem); }

  void check_extensions() {
    for (const std::string& required : doc_.extensions_required) {
      const GltfExtension* known = find_gltf_extension(required);
      if (!known || !known->supported) {
        fail("requires the extension " + required + ", which Atrium does not support" +
             (known ? " (" + std::string(known->effect) + " without it)" : ""));
      }
    }
    for (const std::string& used : doc_.extensions_used) {
      if (std::find(doc_.extensions_required.begin(), doc_.extensions_required.end(), used) != doc_.extensions_required.end()) continue;
      const GltfExtension* known = find_gltf_extension(used);
      if (!known) warn("ignores the optional extension " + used + ", which Atrium does not know");
      else if (!known->supported && !known->effect.empty()) warn("ignores the optional extension " + used + ": " + std::string(known->effect));
    }
  }

  // --- buffer views ----------------------------------------------------------

  void decode_compressed_views() {
    decoded_.resize(doc_.buffer_views.size());
    for (std::size_t v = 0; v < doc_.buffer_views.size(); ++v) {
      if (doc_.buffer_views[v].meshopt) decoded_[v] = gltf::decode_meshopt(doc_, v, budget_);
    }
  }

  // A bufferView's bytes (decoded where it is compressed).
  std::span<const std::uint8_t> view_bytes(std::size_t v) const {
    const gltf::BufferView& view = doc_.buffer_views[v];
    if (view.meshopt) return decoded_[v];
    return {doc_.buffers[view.buffer].data.data() + view.byte_offset, view.byte_length};
  }

  // --- accessors -------------------------------------------------------------

  // Where an accessor's elements come from: its bufferView, or (for a Draco
  // primitive's accessors) the decoded bytes, tightly packed.
  // (Draco's count and index type are the decoded ones, not the declared.)
  struct Elements {
    const std::uint8_t* data = nullptr;  // nullptr: every element is zero
    std::size_t stride = 0;
    std::size_t count = 0;
    int component_type = 0;
  };

  using DecodedAccessors = std::map<int, gltf::DecodedAccessor>;

  Elements elements(int index, const DecodedAccessors* decoded) const {
    const Accessor& a = doc_.accessors[static_cast<std::size_t>(index)];
    if (decoded) {
      const auto it = decoded->find(index);
      if (it != decoded->end()) {
        const gltf::DecodedAccessor& d = it->second;
        return {d.bytes.data(), gltf::component_size(d.component_type) * static_cast<std::size_t>(a.components), d.count, d.component_type};
      }
    }
    if (a.buffer_view < 0) return {nullptr, 0, a.count, a.component_type};
    const gltf::BufferView& view = doc_.buffer_views[static_cast<std::size_t>(a.buffer_view)];
    // The document checked that every element lies inside the view.
    return {view_bytes(static_cast<std::size_t>(a.buffer_view)).data() + a.byte_offset, view.byte_stride ? view.byte_stride : a.element_size(),
            a.count, a.component_type};
  }

  // All elements of an accessor as floats, `components` per element, with
  // normalisation and sparse substitution applied.
  std::vector<float> read_floats(int index, std::initializer_list<int> components, const std::string& what,
                                 const DecodedAccessors* decoded = nullptr) const {
    const Accessor& a = doc_.accessors[static_cast<std::size_t>(index)];
    if (std::find(components.begin(), components.end(), a.components) == components.end()) {
      fail(what + " is " + accessor_name(index) + ", of type " + a.type + "; expected " + (components.size() > 1 ? "VEC3 or VEC4" :
           *components.begin() == 1 ? "SCALAR" : "VEC" + std::to_string(*components.begin())));
    }
    const Elements source = elements(index, decoded);
    const std::size_t size = gltf::component_size(source.component_type);
    const std::size_t n = static_cast<std::size_t>(a.components);
    std::vector<float> out(budget_.bytes(source.count, n * sizeof(float), accessor_name(index)) / sizeof(float), 0.0f);
    if (source.data) {
      for (std::size_t i = 0; i < source.count; ++i) {
        for (std::size_t c = 0; c < n; ++c) {
          out[i * n + c] = to_float(source.data + i * source.stride + c * size, source.component_type, a.normalized);
        }
      }
    }
    if (a.sparse) {
      const Accessor::Sparse& s = *a.sparse;
      const std::size_t index_size = gltf::component_size(s.indices_component_type);
      const std::uint8_t* indices = view_bytes(s.indices_view).data() + s.indices_offset;
      const std::uint8_t* values = view_bytes(s.values_view).data() + s.values_offset;
      for (std::size_t i = 0; i < s.count; ++i) {
        const std::uint32_t target = to_index(indices + i * index_size, s.indices_component_type);
        if (target >= source.count) {
          fail(accessor_name(index) + "/sparse substitutes element " + std::to_string(target) + " of " + std::to_string(source.count));
        }
        for (std::size_t c = 0; c < n; ++c) out[target * n + c] = to_float(values + (i * n + c) * size, a.component_type, a.normalized);
      }
    }
    return out;
  }

  std::vector<std::uint32_t> read_indices(int index, std::size_t vertex_count, const std::string& what,
                                          const DecodedAccessors* decoded) const {
    const Accessor& a = doc_.accessors[static_cast<std::size_t>(index)];
    if (a.components != 1) fail(what + ": the index accessor " + accessor_name(index) + " is " + a.type + ", not SCALAR");
    if (a.component_type != gltf::kUnsignedByte && a.component_type != gltf::kUnsignedShort && a.component_type != gltf::kUnsignedInt) {
      fail(what + ": indices must be unsigned integers (" + accessor_name(index) + " has componentType " + std::to_string(a.component_type) + ")");
    }
    if (a.sparse) fail(what + ": the index accessor " + accessor_name(index) + " is sparse, which glTF does not allow for indices");
    const Elements source = elements(index, decoded);
    if (!source.data) fail(what + ": the index accessor " + accessor_name(index) + " has no data");
    std::vector<std::uint32_t> out(budget_.bytes(source.count, sizeof(std::uint32_t), accessor_name(index)) / sizeof(std::uint32_t));
    for (std::size_t i = 0; i < source.count; ++i) {
      out[i] = to_index(source.data + i * source.stride, source.component_type);
      if (out[i] >= vertex_count) {
        fail(what + ": index " + std::to_string(out[i]) + " is out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
    return out;
  }

  // --- meshes ----------------------------------------------------------------

  static VertexSource vertex_source(const gltf::Primitive& prim) {
    auto get = [&](const char* semantic) {
      const auto it = prim.attributes.find(semantic);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    return {get("POSITION"), get("NORMAL"), get("TANGENT"), get("TEXCOORD_0"), get("TEXCOORD_1"), get("COLOR_0")};
  }

  // The vertices `source` names, one per element of its POSITION accessor.
  std::vector<Vertex> read_vertices(const VertexSource& source, const std::string& what, const DecodedAccessors* decoded, BufferState& state) {
    const std::vector<float> positions = read_floats(source.position, {3}, what + " POSITION", decoded);
    const std::size_t count = positions.size() / 3;
    std::vector<Vertex> vertices(budget_.bytes(count, sizeof(Vertex), what + " vertices") / sizeof(Vertex));
    for (std::size_t i = 0; i < count; ++i) vertices[i].position = glm::make_vec3(&positions[i * 3]);
    auto attribute = [&](int index, const char* name, std::initializer_list<int> components, auto&& store) {
      if (index < 0) return false;
      const std::vector<float> values = read_floats(index, components, what + " " + name, decoded);
      const std::size_t n = static_cast<std::size_t>(doc_.accessors[static_cast<std::size_t>(index)].components);
      if (values.size() != count * n) {
        fail(what + " " + name + " has " + std::to_string(values.size() / n) + " elements, POSITION has " + std::to_string(count));
      }
      for (std::size_t i = 0; i < count; ++i) store(vertices[i], &values[i * n], n);
      return true;
    };
    state.given_normals = attribute(source.normal, "NORMAL", {3}, [](Vertex& v, const float* f, std::size_t) { v.normal = glm::make_vec3(f); });
    state.given_tangents = attribute(source.tangent, "TANGENT", {4}, [](Vertex& v, const float* f, std::size_t) { v.tangent = glm::make_vec4(f); });
    attribute(source.uv0, "TEXCOORD_0", {2}, [](Vertex& v, const float* f, std::size_t) { v.uv0 = glm::make_vec2(f); });
    attribute(source.uv1, "TEXCOORD_1", {2}, [](Vertex& v, const float* f, std::size_t) { v.uv1 = glm::make_vec2(f); });
    attribute(source.color, "COLOR_0", {3, 4}, [](Vertex& v, const float* f, std::size_t n) {
      for (std::size_t c = 0; c < n; ++c) v.color[c] = to_unorm16(f[c]);
    });
    state.first_user = what;
    return vertices;
  }

  std::uint32_t add_vertex_buffer(MeshAsset& asset, std::vector<Vertex> vertices, BufferState state) {
    asset.vertex_buffers.push_back(std::move(vertices));
    buffer_states_.push_back(std::move(state));
    return static_cast<std::uint32_t>(asset.vertex_buffers.size() - 1);
  }

  // Strips and fans as triangle lists; the parity flip keeps strips' winding.
  static std::vector<std::uint32_t> to_triangle_list(std::vector<std::uint32_t> indices, int mode) {
    if (mode == 4) {
      indices.resize(indices.size() / 3 * 3);
      return indices;
    }
    std::vector<std::uint32_t> list;
    for (std::size_t i = 2; i < indices.size(); ++i) {
      if (mode == 5) {
        if (i % 2 == 0) list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
        else list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});
      } else {
        list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
      }
    }
    return list;
  }

  Mesh read_mesh(std::size_t m, MeshAsset& asset) {
    const gltf::Mesh& source = doc_.meshes[m];
    Mesh mesh;
    mesh.name = source.name.empty() ? "mesh " + std::to_string(m) : source.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      const gltf::Primitive& prim = source.primitives[p];
      const std::string what = (gltf::element("meshes", m) / "primitives" / p).str();
      if (prim.mode < 4) {
        static const char* const kModes[] = {"points", "lines", "a line loop", "a line strip"};
        warn(what + " draws " + kModes[prim.mode] + ", not triangles, and is skipped");
        continue;
      }
      VertexSource source_accessors = vertex_source(prim);
      if (source_accessors.position < 0) {
        warn(what + " has no POSITION and is skipped");
        continue;
      }
      gltf::DecodedDraco decoded;
      if (prim.draco) {
        decoded = gltf::decode_draco(doc_, prim, view_bytes(prim.draco->buffer_view), what, budget_);
        for (const std::string& line : decoded.warnings) warn(line);
      }
      const DecodedAccessors* draco = prim.draco ? &decoded.accessors : nullptr;
      // Without normals the spec asks for flat ones: every triangle gets
      // vertices of its own, so such primitives never share.
      const bool flat = source_accessors.normal < 0;
      const bool shared = !draco && !flat && buffers_by_source_.contains(source_accessors);
      BufferState state;
      std::vector<Vertex> vertices;
      if (!shared) vertices = read_vertices(source_accessors, what, draco, state);
      const std::vector<Vertex>& reached = shared ? asset.vertex_buffers[buffers_by_source_.at(source_accessors)] : vertices;
      const std::size_t count = reached.size();
      std::vector<std::uint32_t> indices;
      if (prim.indices >= 0) {
        indices = read_indices(prim.indices, count, what, draco);
      } else {
        indices.resize(count);
        for (std::size_t i = 0; i < count; ++i) indices[i] = static_cast<std::uint32_t>(i);
      }
      Primitive out;
      out.indices = to_triangle_list(std::move(indices), prim.mode);
      triangles_read_ += out.indices.size() / 3;
      drop_unusable_triangles(reached, out, what);
      out.material = prim.material >= 0 ? static_cast<std::uint32_t>(prim.material) : default_material(asset.materials);
      if (flat) {
        std::vector<Vertex> own(budget_.bytes(out.indices.size(), sizeof(Vertex), what + " vertices") / sizeof(Vertex));
        for (std::size_t i = 0; i < out.indices.size(); ++i) {
          own[i] = vertices[out.indices[i]];
          out.indices[i] = static_cast<std::uint32_t>(i);
        }
        generate_normals(own, out.indices);
        state.given_normals = true;  // now they are, and flat
        out.vertex_buffer = add_vertex_buffer(asset, std::move(own), std::move(state));
      } else if (shared) {
        out.vertex_buffer = buffers_by_source_.at(source_accessors);
      } else {
        out.vertex_buffer = add_vertex_buffer(asset, std::move(vertices), std::move(state));
        if (!draco) buffers_by_source_.emplace(source_accessors, out.vertex_buffer);
      }
      BufferState& used = buffer_states_[out.vertex_buffer];
      used.triangles.insert(used.triangles.end(), out.indices.begin(), out.indices.end());
      mesh.primitives.push_back(std::move(out));
    }
    return mesh;
  }

  // Once every primitive is read: normals repaired and tangents generated over
  // all the triangles that use each vertex buffer, then each primitive's bounds.
  void finish_vertex_buffers(MeshAsset& asset) {
    for (std::size_t b = 0; b < asset.vertex_buffers.size(); ++b) {
      std::vector<Vertex>& vertices = asset.vertex_buffers[b];
      const BufferState& state = buffer_states_[b];
      if (state.given_normals && repair_normals(vertices, state.triangles)) {
        warn(state.first_user + " has zero-length or invalid normals; they were regenerated");
      }
      if (!state.given_tangents || !tangents_valid(vertices)) generate_tangents(vertices, state.triangles);
    }
    for (Mesh& mesh : asset.meshes) {
      for (Primitive& p : mesh.primitives) compute_bounds(asset.vertex_buffers[p.vertex_buffer], p);
    }
  }

  void drop_unusable_triangles(const std::vector<Vertex>& vertices, Primitive& p, const std::string& what) {
    const DroppedTriangles dropped = assets::drop_unusable_triangles(vertices, p.indices);
    non_finite_.add(dropped.non_finite, what);
    zero_area_.add(dropped.zero_area, what);
  }

  // One warning per reason for the whole file, however many primitives it hits.
  void warn_skipped(const Skipped& skipped, const char* reason) {
    if (skipped.count == 0) return;
    warn(skipped.where("primitives") + ": " + std::to_string(skipped.count) + " of " + std::to_string(triangles_read_) + " triangles " +
         reason + "; they are skipped");
  }

  std::uint32_t default_material(std::vector<Material>& materials) {
    if (!default_material_) {
      Material m;
      m.name = "default";
      materials.push_back(m);
      default_material_ = static_cast<std::uint32_t>(materials.size() - 1);
    }
    return *default_material_;
  }

  // --- materials and textures ----------------------------------------------

  static double number(const Json& object, const char* key, double fallback) {
    if (!object.is_object()) return fallback;
    const auto it = object.find(key);
    return it != object.end() && it->is_number() && std::isfinite(it->get<double>()) ? it->get<double>() : fallback;
  }

  static glm::vec2 vec2(const Json& object, const char* key, glm::vec2 fallback) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number()) return fallback;
    const glm::vec2 v((*it)[0].get<double>(), (*it)[1].get<double>());
    return std::isfinite(v.x) && std::isfinite(v.y) ? v : fallback;
  }

  TextureSlot texture_slot(const gltf::TextureInfo& info, ColorSpace space, const std::string& what) {
    TextureSlot slot;
    if (info.index < 0) return slot;
    const gltf::Texture& texture = doc_.textures[static_cast<std::size_t>(info.index)];
    slot.uv_set = static_cast<std::uint8_t>(std::clamp(info.tex_coord, 0, 1));
    if (info.tex_coord > 1) warn(what + " uses TEXCOORD_" + std::to_string(info.tex_coord) + "; only 0 and 1 are read, 1 is used");
    if (texture.sampler >= 0) {
      const gltf::Sampler& s = doc_.samplers[static_cast<std::size_t>(texture.sampler)];
      if (s.mag_filter > 0) slot.sampler.mag_filter = static_cast<std::uint16_t>(s.mag_filter);
      if (s.min_filter > 0) slot.sampler.min_filter = static_cast<std::uint16_t>(s.min_filter);
      slot.sampler.wrap_s = static_cast<std::uint16_t>(s.wrap_s);
      slot.sampler.wrap_t = static_cast<std::uint16_t>(s.wrap_t);
    }
    const auto transform = info.extensions.find("KHR_texture_transform");
    if (transform != info.extensions.end() && transform->is_object()) {
      const glm::vec2 offset = vec2(*transform, "offset", glm::vec2(0.0f));
      const glm::vec2 scale = vec2(*transform, "scale", glm::vec2(1.0f));
      const float rotation = static_cast<float>(number(*transform, "rotation", 0.0));
      if (transform->contains("texCoord")) slot.uv_set = static_cast<std::uint8_t>(std::clamp(static_cast<int>(number(*transform, "texCoord", 0)), 0, 1));
      const float c = std::cos(rotation), s = std::sin(rotation);
      const glm::mat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
      const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);
      const glm::mat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
      slot.uv_transform = translate * rotate * scaling;
    }
    // DDS (MSFT_texture_dds) first: it stays block-compressed on the GPU.
    const int image = texture.dds_source >= 0 ? texture.dds_source : texture.source;
    if (image < 0) {
      warn(what + " uses " + gltf::element("textures", static_cast<std::size_t>(info.index)).str() + ", which has no image Atrium can read; a neutral default is used");
      return slot;
    }
    pending_slots_.push_back({image, space});
    return slot;
  }

  std::vector<Material> read_materials() {
    std::vector<Material> materials;
    for (std::size_t i = 0; i < doc_.materials.size(); ++i) {
      const gltf::Material& src = doc_.materials[i];
      const std::string what = gltf::element("materials", i).str() + (src.name.empty() ? "" : " '" + src.name + "'");
      Material m;
      m.name = src.name.empty() ? "material " + std::to_string(i) : src.name;
      m.base_color_factor = glm::vec4(src.base_color_factor[0], src.base_color_factor[1], src.base_color_factor[2], src.base_color_factor[3]);
      m.metallic_factor = static_cast<float>(src.metallic_factor);
      m.roughness_factor = static_cast<float>(src.roughness_factor);
      m.emissive_factor = glm::vec3(src.emissive_factor[0], src.emissive_factor[1], src.emissive_factor[2]);
      const auto strength = src.extensions.find("KHR_materials_emissive_strength");
      if (strength != src.extensions.end()) m.emissive_strength = static_cast<float>(number(*strength, "emissiveStrength", 1.0));
      m.unlit = src.extensions.contains("KHR_materials_unlit");
      m.normal_scale = static_cast<float>(src.normal.scale);
      m.occlusion_strength = static_cast<float>(src.occlusion.scale);
      m.alpha_mode = src.alpha_mode == "MASK" ? AlphaMode::Mask : src.alpha_mode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
      m.alpha_cutoff = static_cast<float>(src.alpha_cutoff);
      m.double_sided = src.double_sided;
      const std::size_t material_index = materials.size();
      auto slot = [&](TextureSlot Material::*member, const gltf::TextureInfo& info, ColorSpace space) {
        const std::size_t before = pending_slots_.size();
        m.*member = texture_slot(info, space, what);
        if (pending_slots_.size() > before) {
          pending_slots_.back().material = material_index;
          pending_slots_.back().member = member;
        }
      };
      slot(&Material::base_color_texture, src.base_color, ColorSpace::Srgb);
      slot(&Material::metallic_roughness_texture, src.metallic_roughness, ColorSpace::Linear);
      slot(&Material::normal_texture, src.normal, ColorSpace::Linear);
      slot(&Material::occlusion_texture, src.occlusion, ColorSpace::Linear);
      slot(&Material::emissive_texture, src.emissive, ColorSpace::Srgb);
      materials.push_back(m);
    }
    return materials;
  }

  // Decodes every image some material uses, once per (image, colour space), on
  // worker threads, and points the materials' slots at the results.
  void decode_images(std::vector<Material>& materials) {
    std::map<std::pair<int, ColorSpace>, std::size_t> jobs_by_key;
    struct Job {
      int image;
      ColorSpace space;
      TextureData decoded;
      std::string error;
    };
    std::vector<Job> jobs;
    for (const PendingSlot& pending : pending_slots_) {
      const auto key = std::make_pair(pending.image, pending.space);
      if (!jobs_by_key.contains(key)) {
        jobs_by_key[key] = jobs.size();
        jobs.push_back({pending.image, pending.space, {}, {}});
      }
    }
    std::vector<DecodedTexture> decoded = decode_in_parallel(
        jobs.size(),
        [&](std::size_t j) {
          const gltf::Image& image = doc_.images[static_cast<std::size_t>(jobs[j].image)];
          std::vector<std::uint8_t> file_bytes;
          std::span<const std::uint8_t> bytes;
          DecodedTexture result;
          if (image.buffer_view >= 0) {
            bytes = view_bytes(static_cast<std::size_t>(image.buffer_view));
          } else if (!image.uri.empty()) {
            file_bytes = gltf::read_image_uri(doc_, image.uri, budget_, result.error);
            bytes = file_bytes;
          } else {
            result.error = "no image data";
          }
          return result.error.empty() ? decode_texture(bytes, jobs[j].space, budget_.limit()) : result;
        },
        threads_, progress_);
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      if (decoded[j].texture) jobs[j].decoded = std::move(*decoded[j].texture);
      else jobs[j].error = std::move(decoded[j].error);
    }

    const std::string canonical = fs::weakly_canonical(path_).string();
    std::vector<TextureHandle> handles(jobs.size());
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const gltf::Image& image = doc_.images[static_cast<std::size_t>(jobs[j].image)];
      const std::string label = gltf::element("images", static_cast<std::size_t>(jobs[j].image)).str() +
                                (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "" : " (" + image.uri + ")");
      if (!jobs[j].error.empty()) {
        warn(label + " cannot be decoded (" + jobs[j].error + "); a neutral default texture is used");
        continue;
      }
      const std::string key = canonical + "#image" + std::to_string(jobs[j].image) + (jobs[j].space == ColorSpace::Srgb ? "/srgb" : "/linear");
      jobs[j].decoded.name = label;
      handles[j] = assets_.add_texture(std::move(jobs[j].decoded), key);
      ++result_.images;
    }
    for (const PendingSlot& pending : pending_slots_) {
      (materials[pending.material].*pending.member).texture = handles[jobs_by_key.at({pending.image, pending.space})];
    }
    // Images no material uses are not decoded; a broken one still deserves a word.
    for (std::size_t i = 0; i < doc_.images.size(); ++i) {
      const gltf::Image& image = doc_.images[i];
      const bool used = std::any_of(jobs.begin(), jobs.end(), [&](const Job& job) { return job.image == static_cast<int>(i); });
      if (used || image.uri.empty()) continue;
      const std::string problem = gltf::image_uri_problem(doc_, image.uri);
      if (!problem.empty()) warn(gltf::element("images", i).str() + " cannot be read (" + problem + "); no material uses it");
    }
  }

  // --- nodes, instances and lights ------------------------------------------

  // EXT_mesh_gpu_instancing: the node's per-instance transforms (local, before
  // the node's own world matrix).
  std::vector<glm::mat4> instance_matrices(const gltf::Node::Instancing& instancing, const std::string& where) {
    std::size_t count = 0;
    bool any = false;
    std::vector<float> t, r, s;
    auto read = [&](int accessor, std::initializer_list<int> components, const char* name, std::vector<float>& out) {
      if (accessor < 0) return;
      out = read_floats(accessor, components, where + " " + name);
      const std::size_t n = doc_.accessors[static_cast<std::size_t>(accessor)].count;
      if (any && n != count) fail(where + " " + name + " has " + std::to_string(n) + " instances, the other attributes " + std::to_string(count));
      count = n;
      any = true;
    };
    read(instancing.translation, {3}, "TRANSLATION", t);
    read(instancing.rotation, {4}, "ROTATION", r);
    read(instancing.scale, {3}, "SCALE", s);
    std::vector<glm::mat4> matrices(budget_.bytes(count, sizeof(glm::mat4), where) / sizeof(glm::mat4));
    for (std::size_t i = 0; i < count; ++i) {
      glm::mat4 m(1.0f);
      if (!t.empty()) m = glm::translate(m, glm::make_vec3(&t[i * 3]));
      if (!r.empty()) {
        const glm::quat q(r[i * 4 + 3], r[i * 4], r[i * 4 + 1], r[i * 4 + 2]);
        const float length = glm::length(q);
        m *= glm::mat4_cast(length > 1e-6f && std::isfinite(length) ? q / length : glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
      }
      if (!s.empty()) m = glm::scale(m, glm::make_vec3(&s[i * 3]));
      matrices[i] = m;
    }
    return matrices;
  }

  void add_instance(const MeshAsset& asset, int mesh, const glm::mat4& world, const std::string& where) {
    SceneInstance instance;
    instance.mesh = static_cast<std::uint32_t>(mesh);
    const std::optional<Transform> transform = from_matrix(world);
    if (!transform) {
      skipped_instances_.add(1, where);
      return;
    }
    instance.transform = *transform;
    result_.instances.push_back(instance);
    for (const Primitive& p : asset.meshes[static_cast<std::size_t>(mesh)].primitives) {
      if (!p.indices.empty()) bounds_.add_box(world, p.bounds_min, p.bounds_max);
    }
  }

  void place_nodes(const MeshAsset& asset) {
    std::vector<int> roots;
    if (!doc_.scenes.empty()) {
      roots = doc_.scenes[static_cast<std::size_t>(doc_.scene >= 0 ? doc_.scene : 0)];
    } else {
      // No scene: every node that is nobody's child is a root.
      std::vector<bool> is_child(doc_.nodes.size(), false);
      for (const auto& node : doc_.nodes) {
        for (int child : node.children) is_child[static_cast<std::size_t>(child)] = true;
      }
      for (std::size_t n = 0; n < doc_.nodes.size(); ++n) {
        if (!is_child[n]) roots.push_back(static_cast<int>(n));
      }
    }
    std::vector<bool> visited(doc_.nodes.size(), false);
    // Depth first, without recursion: a hostile file may nest nodes deeply.
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::mat4(1.0f));
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (visited[static_cast<std::size_t>(index)]) fail(gltf::element("nodes", static_cast<std::size_t>(index)).str() + " appears twice in the hierarchy (a cycle?)");
      visited[static_cast<std::size_t>(index)] = true;
      const gltf::Node& node = doc_.nodes[static_cast<std::size_t>(index)];
      const glm::mat4 world = parent * node.local;
      const std::string where = gltf::element("nodes", static_cast<std::size_t>(index)).str();
      if (node.mesh >= 0 && node.instancing) {
        for (const glm::mat4& instance : instance_matrices(*node.instancing, where + " EXT_mesh_gpu_instancing")) {
          add_instance(asset, node.mesh, world * instance, where);
        }
      } else if (node.mesh >= 0) {
        add_instance(asset, node.mesh, world, where);
      }
      if (node.light >= 0) add_light(node.light, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.emplace_back(*child, world);
    }
    result_.bounds = bounds_;
    if (skipped_instances_.count > 0) {
      warn(skipped_instances_.where("nodes") + ": " + std::to_string(skipped_instances_.count) +
           " instances have a transform with a zero or non-finite scale; they are skipped");
    }
  }

  void add_light(int index, const glm::mat4& world) {
    const gltf::Light& src = doc_.lights[static_cast<std::size_t>(index)];
    SceneLight light;
    light.position = glm::vec3(world[3]);
    light.direction = glm::normalize(glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)));
    light.color = glm::vec3(src.color[0], src.color[1], src.color[2]);
    light.intensity = static_cast<float>(src.intensity) / kLumensPerWatt;
    if (src.range > 0.0) light.radius = static_cast<float>(src.range);
    const std::string name = (JsonPointer() / "extensions" / "KHR_lights_punctual" / "lights" / static_cast<std::size_t>(index)).str() + (src.name.empty() ? "" : " '" + src.name + "'");
    if (src.type == "directional") {
      light.kind = LightKind::Directional;
    } else if (src.type == "spot") {
      light.kind = LightKind::Spot;
      light.inner_cone = static_cast<float>(src.inner_cone);
      light.outer_cone = static_cast<float>(src.outer_cone);
    } else if (src.type != "point") {
      warn(name + " has the unknown type '" + src.type + "' and is skipped");
      return;
    }
    // A light that would poison every pixel it reaches (NaN, infinity) or give
    // nothing (zero, negative) is dropped; the rest of the model still loads.
    if (!std::isfinite(light.intensity) || light.intensity <= 0.0f) {
      warn(name + " has intensity " + std::to_string(src.intensity) + " (expected a positive number) and is skipped");
      return;
    }
    if (!finite(light.color) || glm::any(glm::lessThan(light.color, glm::vec3(0.0f)))) {
      warn(name + " has a negative or non-finite colour and is skipped");
      return;
    }
    if (!finite(light.position) || !finite(light.direction) || (light.radius && !std::isfinite(*light.radius))) {
      warn(name + " ends up at a non-finite position, direction or range (its node transforms) and is skipped");
      return;
    }
    result_.lights.push_back(light);
  }

  struct PendingSlot {
    int image = -1;
    ColorSpace space = ColorSpace::Linear;
    std::size_t material = 0;
    TextureSlot Material::*member = nullptr;
  };

  fs::path path_;
  std::string name_;
  AssetManager& assets_;
  const ProgressCallback& progress_;
  unsigned threads_ = 0;
  MemoryBudget budget_;
  gltf::Document doc_;
  std::vector<std::vector<std::uint8_t>> decoded_;
  std::map<VertexSource, std::uint32_t> buffers_by_source_;
  std::vector<BufferState> buffer_states_;
  std::vector<PendingSlot> pending_slots_;
  std::optional<std::uint32_t> default_material_;
  Skipped non_finite_, zero_area_, skipped_instances_;
  std::size_t triangles_read_ = 0;
  Box bounds_;
  ModelImport result_;
};

}  // namespace

ModelImport import_gltf(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  return refuse_out_of_memory(path, [&] { return Importer(path, assets, options).run(); });
}

}  // namespace atrium::assets
