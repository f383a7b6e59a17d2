#include "assets/gltf_import.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <meshoptimizer.h>
#include <stb_image.h>
#include <tiny_gltf.h>

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Keeps the encoded bytes: images are decoded later, in parallel.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// tinygltf's own file reader allocates whatever size a directory reports;
// these callbacks read regular files only.
bool regular_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool read_regular_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    if (err) *err += "'" + path + "' is not a readable file\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    if (err) *err += "cannot read '" + path + "'\n";
    return false;
  }
  return true;
}

std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  // tinygltf passes on nlohmann's "[json.exception.out_of_range.406] " tags.
  if (line.starts_with("[json.exception.") && line.find("] ") != std::string::npos) {
    line = "not valid JSON (" + line.substr(line.find("] ") + 2) + ")";
  }
  return line;
}

class Importer {
 public:
  Importer(const fs::path& path, AssetManager& assets, const ImportOptions& options)
      : path_(path), name_(path.string()), assets_(assets), progress_(options.progress), threads_(options.decode_threads) {}

  GltfImport run() {
    const auto start = Clock::now();
    load();
    check_extensions();
    decode_buffer_views();
    MeshAsset asset;
    asset.name = path_.filename().string();
    asset.materials = read_materials();
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) asset.meshes.push_back(read_mesh(m, asset.materials));
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
  // Triangles left out, counted over every primitive (see drop_unusable_triangles).
  struct SkippedTriangles {
    std::size_t triangles = 0, primitives = 0;
    std::string first;  // "mesh 3 primitive 0"
    void add(std::size_t count, const std::string& primitive) {
      if (count == 0) return;
      if (primitives++ == 0) first = primitive;
      triangles += count;
    }
  };

  [[noreturn]] void fail(const std::string& problem) const { throw ImportError(name_ + ": " + problem); }
  void warn(const std::string& problem) { result_.warnings.push_back(name_ + ": " + problem); }

  void load() {
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec)) fail("no such file");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded_image, nullptr);
    loader.SetFsCallbacks({regular_file_exists, tinygltf::ExpandFilePath, read_regular_file, tinygltf::WriteWholeFile, nullptr});
    std::string error, warning;
    std::string extension = path_.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
    const bool ok = extension == ".glb" ? loader.LoadBinaryFromFile(&model_, &error, &warning, path_.string())
                                        : loader.LoadASCIIFromFile(&model_, &error, &warning, path_.string());
    if (!ok) fail(error.empty() ? "not a valid glTF file" : first_line(error));
    // tinygltf reports images it could not read as errors next to a valid model.
    for (std::size_t pos = 0; !error.empty() && pos < error.size();) {
      const std::size_t end = error.find('\n', pos);
      const std::string line = error.substr(pos, end - pos);
      if (!line.empty()) warn(line);
      pos = end == std::string::npos ? error.size() : end + 1;
    }
    if (!warning.empty()) warn(first_line(warning));
  }

  void check_extensions() {
    const auto& supported = supported_gltf_extensions();
    for (const std::string& required : model_.extensionsRequired) {
      if (std::find(supported.begin(), supported.end(), required) == supported.end()) {
        fail("requires the extension " + required + ", which Atrium does not support");
      }
    }
    for (const std::string& used : model_.extensionsUsed) {
      if (std::find(supported.begin(), supported.end(), used) == supported.end()) {
        warn("ignores the optional extension " + used);
      }
    }
  }

  // --- buffers -------------------------------------------------------------

  struct ByteRange {
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    std::size_t stride = 0;  // 0 = tightly packed
  };

  // Every bufferView's bytes, decompressed where EXT_meshopt_compression says so.
  void decode_buffer_views() {
    views_.resize(model_.bufferViews.size());
    decoded_.resize(model_.bufferViews.size());
    for (std::size_t v = 0; v < model_.bufferViews.size(); ++v) {
      const tinygltf::BufferView& view = model_.bufferViews[v];
      const auto meshopt = view.extensions.find("EXT_meshopt_compression");
      if (meshopt != view.extensions.end()) {
        decode_meshopt(v, meshopt->second);
        continue;
      }
      views_[v] = {slice(view.buffer, view.byteOffset, view.byteLength, "bufferView " + std::to_string(v)), view.byteLength,
                   view.byteStride};
    }
  }

  const std::uint8_t* slice(int buffer, std::size_t offset, std::size_t length, const std::string& what) const {
    if (buffer < 0 || static_cast<std::size_t>(buffer) >= model_.buffers.size()) {
      fail(what + " refers to buffer " + std::to_string(buffer) + ", which does not exist");
    }
    const auto& data = model_.buffers[static_cast<std::size_t>(buffer)].data;
    if (offset > data.size() || length > data.size() - offset) {
      fail(what + " reads bytes " + std::to_string(offset) + ".." + std::to_string(offset + length) + " of buffer " +
           std::to_string(buffer) + ", which has " + std::to_string(data.size()));
    }
    return data.data() + offset;
  }

  void decode_meshopt(std::size_t v, const tinygltf::Value& ext) {
    const std::string what = "bufferView " + std::to_string(v) + " (EXT_meshopt_compression)";
    auto number = [&](const char* key, bool required) -> std::size_t {
      if (!ext.Has(key)) {
        if (required) fail(what + " lacks " + key);
        return 0;
      }
      const double value = ext.Get(key).GetNumberAsDouble();
      if (!(value >= 0.0) || value > 4.0e9) fail(what + " has an invalid " + key);
      return static_cast<std::size_t>(value);
    };
    const std::size_t stride = number("byteStride", true), count = number("count", true);
    const std::size_t offset = number("byteOffset", false), length = number("byteLength", true);
    const int buffer = static_cast<int>(number("buffer", true));
    const std::string mode = ext.Has("mode") ? ext.Get("mode").Get<std::string>() : "";
    const std::string filter = ext.Has("filter") ? ext.Get("filter").Get<std::string>() : "NONE";
    if (stride == 0 || count == 0 || stride > 256) fail(what + " has an invalid byteStride or count");
    const std::uint8_t* source = slice(buffer, offset, length, what);
    std::vector<std::uint8_t>& out = decoded_[v];
    out.resize(stride * count);
    int status = -1;
    if (mode == "ATTRIBUTES") status = meshopt_decodeVertexBuffer(out.data(), count, stride, source, length);
    else if (mode == "TRIANGLES") status = meshopt_decodeIndexBuffer(out.data(), count, stride, source, length);
    else if (mode == "INDICES") status = meshopt_decodeIndexSequence(out.data(), count, stride, source, length);
    else fail(what + " has an unknown mode '" + mode + "'");
    if (status != 0) fail(what + " cannot be decoded (corrupt data)");
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), count, stride);
    else if (filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), count, stride);
    else if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), count, stride);
    else if (filter != "NONE") fail(what + " has an unknown filter '" + filter + "'");
    views_[v] = {out.data(), out.size(), stride};
  }

  // --- accessors -----------------------------------------------------------

  static std::size_t component_size(int type) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
      case TINYGLTF_COMPONENT_TYPE_SHORT:
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
      default: return 0;
    }
  }

  static float to_float(const std::uint8_t* p, int type, bool normalized) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<std::int8_t>(*p);
        return normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0f : static_cast<float>(*p);
      case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0f : static_cast<float>(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
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

  static std::uint32_t to_index(const std::uint8_t* p, int type) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
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

  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
      fail(what + " refers to accessor " + std::to_string(index) + ", which does not exist");
    }
    return model_.accessors[static_cast<std::size_t>(index)];
  }

  // Bytes of `count` elements of `element_size` from a bufferView, with bounds checked.
  ByteRange element_range(int view_index, std::size_t byte_offset, std::size_t count, std::size_t element_size,
                          const std::string& what) const {
    if (view_index < 0 || static_cast<std::size_t>(view_index) >= views_.size()) {
      fail(what + " refers to bufferView " + std::to_string(view_index) + ", which does not exist");
    }
    ByteRange range = views_[static_cast<std::size_t>(view_index)];
    const std::size_t stride = range.stride ? range.stride : element_size;
    if (count > 0 && (byte_offset > range.size || (count - 1) > (range.size - byte_offset) / stride ||
                      (count - 1) * stride + element_size > range.size - byte_offset)) {
      fail(what + " reads past the end of bufferView " + std::to_string(view_index));
    }
    range.data += byte_offset;
    range.stride = stride;
    return range;
  }

  // All elements of an accessor as floats, `components` per element, with
  // normalisation and sparse substitution applied.
  std::vector<float> read_floats(int index, int components, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const int actual = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    if (actual != components) fail(what + " expects " + std::to_string(components) + " components, accessor " +
                                   std::to_string(index) + " has " + std::to_string(actual));
    const std::size_t size = component_size(a.componentType);
    if (size == 0) fail("accessor " + std::to_string(index) + " has an invalid componentType");
    const std::size_t n = static_cast<std::size_t>(components);
    std::vector<float> out(a.count * n, 0.0f);
    if (a.bufferView >= 0) {
      const ByteRange range = element_range(a.bufferView, a.byteOffset, a.count, size * n, "accessor " + std::to_string(index));
      for (std::size_t i = 0; i < a.count; ++i) {
        for (std::size_t c = 0; c < n; ++c) out[i * n + c] = to_float(range.data + i * range.stride + c * size, a.componentType, a.normalized);
      }
    }
    if (a.sparse.isSparse) {
      const std::string sparse_what = "accessor " + std::to_string(index) + " (sparse)";
      const auto count = static_cast<std::size_t>(a.sparse.count);
      if (count > a.count) fail(sparse_what + " has more substitutions than elements");
      const std::size_t index_size = component_size(a.sparse.indices.componentType);
      const ByteRange indices = element_range(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset),
                                              count, index_size, sparse_what);
      const ByteRange values = element_range(a.sparse.values.bufferView, static_cast<std::size_t>(a.sparse.values.byteOffset),
                                             count, size * n, sparse_what);
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t target = to_index(indices.data + i * index_size, a.sparse.indices.componentType);
        if (target >= a.count) fail(sparse_what + " substitutes element " + std::to_string(target) + " of " + std::to_string(a.count));
        for (std::size_t c = 0; c < n; ++c) out[target * n + c] = to_float(values.data + i * size * n + c * size, a.componentType, a.normalized);
      }
    }
    return out;
  }

  std::vector<std::uint32_t> read_indices(int index, std::size_t vertex_count, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(what + ": the index accessor is not SCALAR");
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      fail(what + ": indices must be unsigned integers");
    }
    if (a.bufferView < 0) fail(what + ": the index accessor has no bufferView");
    const std::size_t size = component_size(a.componentType);
    const ByteRange range = element_range(a.bufferView, a.byteOffset, a.count, size, "accessor " + std::to_string(index));
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
      out[i] = to_index(range.data + i * range.stride, a.componentType);
      if (out[i] >= vertex_count) {
        fail(what + ": index " + std::to_string(out[i]) + " is out of range (" + std::to_string(vertex_count) + " vertices)");
      }
    }
    return out;
  }

  // --- meshes --------------------------------------------------------------

  Mesh read_mesh(std::size_t m, std::vector<Material>& materials) {
    const tinygltf::Mesh& source = model_.meshes[m];
    Mesh mesh;
    mesh.name = source.name.empty() ? "mesh " + std::to_string(m) : source.name;
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = source.primitives[p];
      const std::string what = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
        warn(what + " has mode " + std::to_string(prim.mode) + " (not triangles) and is skipped");
        continue;
      }
      const auto position = prim.attributes.find("POSITION");
      if (position == prim.attributes.end()) {
        warn(what + " has no POSITION and is skipped");
        continue;
      }
      Primitive out;
      const std::vector<float> positions = read_floats(position->second, 3, what + " POSITION");
      const std::size_t count = positions.size() / 3;
      out.vertices.resize(count);
      for (std::size_t i = 0; i < count; ++i) out.vertices[i].position = glm::make_vec3(&positions[i * 3]);
      auto attribute = [&](const char* name, int components, auto&& store) {
        const auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return false;
        const std::vector<float> values = read_floats(it->second, components, what + " " + name);
        if (values.size() != count * static_cast<std::size_t>(components)) {
          fail(what + " " + name + " has " + std::to_string(values.size() / components) + " elements, POSITION has " + std::to_string(count));
        }
        for (std::size_t i = 0; i < count; ++i) store(out.vertices[i], &values[i * static_cast<std::size_t>(components)]);
        return true;
      };
      const bool has_normals = attribute("NORMAL", 3, [](Vertex& v, const float* f) { v.normal = glm::make_vec3(f); });
      const bool has_tangents = attribute("TANGENT", 4, [](Vertex& v, const float* f) { v.tangent = glm::make_vec4(f); });
      attribute("TEXCOORD_0", 2, [](Vertex& v, const float* f) { v.uv0 = glm::make_vec2(f); });
      attribute("TEXCOORD_1", 2, [](Vertex& v, const float* f) { v.uv1 = glm::make_vec2(f); });
      if (prim.indices >= 0) {
        out.indices = read_indices(prim.indices, count, what);
      } else {
        out.indices.resize(count);
        for (std::size_t i = 0; i < count; ++i) out.indices[i] = static_cast<std::uint32_t>(i);
      }
      out.indices.resize(out.indices.size() / 3 * 3);
      triangles_read_ += out.indices.size() / 3;
      drop_unusable_triangles(out, what);
      if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= materials.size()) {
        fail(what + " refers to material " + std::to_string(prim.material) + ", which does not exist");
      }
      out.material = prim.material >= 0 ? static_cast<std::uint32_t>(prim.material) : default_material(materials);
      if (!has_normals) {
        // The spec asks for flat normals: every triangle gets its own vertices.
        std::vector<Vertex> flat;
        flat.reserve(out.indices.size());
        for (std::uint32_t index : out.indices) flat.push_back(out.vertices[index]);
        out.vertices = std::move(flat);
        for (std::size_t i = 0; i < out.indices.size(); ++i) out.indices[i] = static_cast<std::uint32_t>(i);
        generate_normals(out);
      }
      if (has_normals && repair_normals(out)) warn(what + " has zero-length or invalid normals; they were regenerated");
      if (!has_tangents || !tangents_valid(out)) generate_tangents(out);
      compute_bounds(out);
      mesh.primitives.push_back(std::move(out));
    }
    return mesh;
  }

  // Removes triangles with a corner at a NaN or infinite position (or whose
  // normal overflows), which would rasterise garbage and poison normals, and
  // triangles of zero area (a repeated corner, or three corners on one line),
  // which cover no pixel but would give generated normals and tangents a zero
  // vector. Real exports have the latter (the teapot's lid has 8).
  void drop_unusable_triangles(Primitive& p, const std::string& what) {
    auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    std::size_t kept = 0, non_finite = 0, zero_area = 0;
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      const glm::vec3 a = p.vertices[p.indices[t]].position, b = p.vertices[p.indices[t + 1]].position,
                      c = p.vertices[p.indices[t + 2]].position;
      const glm::vec3 n = glm::cross(b - a, c - a);
      if (!finite(a) || !finite(b) || !finite(c) || !finite(n)) {
        ++non_finite;
        continue;
      }
      if (n == glm::vec3(0.0f)) {
        ++zero_area;
        continue;
      }
      for (int k = 0; k < 3; ++k) p.indices[kept * 3 + static_cast<std::size_t>(k)] = p.indices[t + static_cast<std::size_t>(k)];
      ++kept;
    }
    p.indices.resize(kept * 3);
    non_finite_.add(non_finite, what);
    zero_area_.add(zero_area, what);
  }

  // One warning per reason for the whole file, however many primitives it hits.
  void warn_skipped(const SkippedTriangles& skipped, const char* reason) {
    if (skipped.triangles == 0) return;
    const std::string where = skipped.primitives > 1 ? skipped.first + " and " + std::to_string(skipped.primitives - 1) + " more primitives"
                                                     : skipped.first;
    warn(where + ": " + std::to_string(skipped.triangles) + " of " + std::to_string(triangles_read_) + " triangles " + reason +
         "; they are skipped");
  }

  // Normalises given normals; where one is zero-length or not finite, uses the
  // smooth normal computed from the triangles instead. Returns whether any was bad.
  static bool repair_normals(Primitive& p) {
    bool bad = false;
    for (Vertex& v : p.vertices) {
      const float length = glm::length(v.normal);
      if (length > 1e-12f && std::isfinite(length)) v.normal /= length;
      else bad = true;
    }
    if (!bad) return false;
    Primitive smooth = p;
    generate_normals(smooth);
    for (std::size_t i = 0; i < p.vertices.size(); ++i) {
      const float length = glm::length(p.vertices[i].normal);
      if (!(std::abs(length - 1.0f) < 1e-3f)) p.vertices[i].normal = smooth.vertices[i].normal;
    }
    return true;
  }

  static bool tangents_valid(const Primitive& p) {
    return std::all_of(p.vertices.begin(), p.vertices.end(), [](const Vertex& v) {
      const float length = glm::length(glm::vec3(v.tangent));
      return std::isfinite(length) && length > 1e-6f;
    });
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

  static double number(const tinygltf::Value& object, const char* key, double fallback) {
    return object.IsObject() && object.Has(key) && object.Get(key).IsNumber() ? object.Get(key).GetNumberAsDouble() : fallback;
  }

  TextureSlot texture_slot(int texture_index, int tex_coord, const tinygltf::ExtensionMap& extensions, ColorSpace space,
                           const std::string& what) {
    TextureSlot slot;
    if (texture_index < 0) return slot;
    if (static_cast<std::size_t>(texture_index) >= model_.textures.size()) {
      fail(what + " refers to texture " + std::to_string(texture_index) + ", which does not exist");
    }
    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(texture_index)];
    slot.uv_set = static_cast<std::uint8_t>(std::clamp(tex_coord, 0, 1));
    if (tex_coord > 1) warn(what + " uses TEXCOORD_" + std::to_string(tex_coord) + "; only 0 and 1 are read, 1 is used");
    if (texture.sampler >= 0 && static_cast<std::size_t>(texture.sampler) < model_.samplers.size()) {
      const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(texture.sampler)];
      if (s.magFilter > 0) slot.sampler.mag_filter = static_cast<std::uint16_t>(s.magFilter);
      if (s.minFilter > 0) slot.sampler.min_filter = static_cast<std::uint16_t>(s.minFilter);
      slot.sampler.wrap_s = static_cast<std::uint16_t>(s.wrapS);
      slot.sampler.wrap_t = static_cast<std::uint16_t>(s.wrapT);
    }
    const auto transform = extensions.find("KHR_texture_transform");
    if (transform != extensions.end()) {
      const tinygltf::Value& t = transform->second;
      glm::vec2 offset(0.0f), scale(1.0f);
      if (t.Has("offset") && t.Get("offset").ArrayLen() == 2) {
        offset = {t.Get("offset").Get(0).GetNumberAsDouble(), t.Get("offset").Get(1).GetNumberAsDouble()};
      }
      if (t.Has("scale") && t.Get("scale").ArrayLen() == 2) {
        scale = {t.Get("scale").Get(0).GetNumberAsDouble(), t.Get("scale").Get(1).GetNumberAsDouble()};
      }
      const float rotation = static_cast<float>(number(t, "rotation", 0.0));
      if (t.Has("texCoord")) slot.uv_set = static_cast<std::uint8_t>(std::clamp(static_cast<int>(number(t, "texCoord", 0)), 0, 1));
      const float c = std::cos(rotation), s = std::sin(rotation);
      const glm::mat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
      const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);
      const glm::mat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
      slot.uv_transform = translate * rotate * scaling;
    }
    if (texture.source < 0 || static_cast<std::size_t>(texture.source) >= model_.images.size()) {
      warn(what + " uses texture " + std::to_string(texture_index) + ", which has no image; a neutral default is used");
      return slot;
    }
    pending_slots_.push_back({texture.source, space});
    return slot;
  }

  std::vector<Material> read_materials() {
    std::vector<Material> materials;
    for (std::size_t i = 0; i < model_.materials.size(); ++i) {
      const tinygltf::Material& src = model_.materials[i];
      const std::string what = "material " + std::to_string(i) + (src.name.empty() ? "" : " '" + src.name + "'");
      Material m;
      m.name = src.name.empty() ? "material " + std::to_string(i) : src.name;
      const auto& pbr = src.pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() == 4) m.base_color_factor = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
      m.metallic_factor = static_cast<float>(pbr.metallicFactor);
      m.roughness_factor = static_cast<float>(pbr.roughnessFactor);
      if (src.emissiveFactor.size() == 3) m.emissive_factor = glm::vec3(glm::make_vec3(src.emissiveFactor.data()));
      const auto strength = src.extensions.find("KHR_materials_emissive_strength");
      if (strength != src.extensions.end()) m.emissive_strength = static_cast<float>(number(strength->second, "emissiveStrength", 1.0));
      m.normal_scale = static_cast<float>(src.normalTexture.scale);
      m.occlusion_strength = static_cast<float>(src.occlusionTexture.strength);
      m.alpha_mode = src.alphaMode == "MASK" ? AlphaMode::Mask : src.alphaMode == "BLEND" ? AlphaMode::Blend : AlphaMode::Opaque;
      m.alpha_cutoff = static_cast<float>(src.alphaCutoff);
      m.double_sided = src.doubleSided;
      const std::size_t material_index = materials.size();
      auto slot = [&](TextureSlot Material::*member, int texture, int tex_coord, const tinygltf::ExtensionMap& ext, ColorSpace space) {
        const std::size_t before = pending_slots_.size();
        m.*member = texture_slot(texture, tex_coord, ext, space, what);
        if (pending_slots_.size() > before) {
          pending_slots_.back().material = material_index;
          pending_slots_.back().member = member;
        }
      };
      slot(&Material::base_color_texture, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions, ColorSpace::Srgb);
      slot(&Material::metallic_roughness_texture, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
           pbr.metallicRoughnessTexture.extensions, ColorSpace::Linear);
      slot(&Material::normal_texture, src.normalTexture.index, src.normalTexture.texCoord, src.normalTexture.extensions, ColorSpace::Linear);
      slot(&Material::occlusion_texture, src.occlusionTexture.index, src.occlusionTexture.texCoord, src.occlusionTexture.extensions,
           ColorSpace::Linear);
      slot(&Material::emissive_texture, src.emissiveTexture.index, src.emissiveTexture.texCoord, src.emissiveTexture.extensions, ColorSpace::Srgb);
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
      Image decoded;
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
    std::vector<std::pair<const std::uint8_t*, std::size_t>> encoded(jobs.size());
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const tinygltf::Image& image = model_.images[static_cast<std::size_t>(jobs[j].image)];
      if (!image.image.empty()) {
        encoded[j] = {image.image.data(), image.image.size()};
      } else if (image.bufferView >= 0) {
        try {
          const ByteRange range = element_range(image.bufferView, 0, 1, 1, "image " + std::to_string(jobs[j].image));
          encoded[j] = {range.data, range.size};
        } catch (const ImportError& e) {
          jobs[j].error = e.what();
        }
      }
    }
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> finished{0};
    std::mutex progress_mutex;
    auto worker = [&] {
      for (std::size_t j = next++; j < jobs.size(); j = next++) {
        if (progress_ && j > 0) {
          std::lock_guard lock(progress_mutex);
          progress_("decoding images", finished.load(), jobs.size());
        }
        if (!jobs[j].error.empty()) continue;
        if (!encoded[j].first) {
          const std::string& uri = model_.images[static_cast<std::size_t>(jobs[j].image)].uri;
          jobs[j].error = uri.empty() || uri.rfind("data:", 0) == 0 ? "no image data" : "the file is missing or unreadable";
          continue;
        }
        int w = 0, h = 0, channels = 0;
        stbi_uc* pixels = stbi_load_from_memory(encoded[j].first, static_cast<int>(encoded[j].second), &w, &h, &channels, 4);
        if (!pixels) {
          jobs[j].error = stbi_failure_reason();
          continue;
        }
        jobs[j].decoded = Image{w, h, std::vector<std::uint8_t>(pixels, pixels + static_cast<std::size_t>(w) * h * 4)};
        stbi_image_free(pixels);
        ++finished;
      }
    };
    const unsigned threads = threads_ ? threads_ : std::clamp<unsigned>(std::thread::hardware_concurrency(), 1, 16);
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<std::size_t>(threads, jobs.size()); ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();

    const std::string canonical = fs::weakly_canonical(path_).string();
    std::vector<TextureHandle> handles(jobs.size());
    for (std::size_t j = 0; j < jobs.size(); ++j) {
      const tinygltf::Image& image = model_.images[static_cast<std::size_t>(jobs[j].image)];
      const std::string label = "image " + std::to_string(jobs[j].image) + (image.uri.empty() ? "" : " (" + image.uri + ")");
      if (!jobs[j].error.empty()) {
        warn(label + " cannot be decoded (" + jobs[j].error + "); a neutral default texture is used");
        continue;
      }
      const std::string key = canonical + "#image" + std::to_string(jobs[j].image) + (jobs[j].space == ColorSpace::Srgb ? "/srgb" : "/linear");
      handles[j] = assets_.add_texture({label, std::move(jobs[j].decoded), jobs[j].space}, key);
      ++result_.images;
    }
    for (const PendingSlot& pending : pending_slots_) {
      (materials[pending.material].*pending.member).texture = handles[jobs_by_key.at({pending.image, pending.space})];
    }
  }

  // --- nodes and lights ----------------------------------------------------

  static glm::mat4 local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::mat4(glm::make_mat4(node.matrix.data()));
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3) m = glm::translate(m, glm::vec3(glm::make_vec3(node.translation.data())));
    if (node.rotation.size() == 4) {
      m *= glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(glm::make_vec3(node.scale.data())));
    return m;
  }

  void place_nodes(const MeshAsset& asset) {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 && static_cast<std::size_t>(model_.defaultScene) < model_.scenes.size() ? model_.defaultScene : 0;
      roots = model_.scenes[static_cast<std::size_t>(scene)].nodes;
    } else {
      // No scene: every node that is nobody's child is a root.
      std::vector<bool> is_child(model_.nodes.size(), false);
      for (const auto& node : model_.nodes) {
        for (int child : node.children) {
          if (child >= 0 && static_cast<std::size_t>(child) < is_child.size()) is_child[static_cast<std::size_t>(child)] = true;
        }
      }
      for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
        if (!is_child[n]) roots.push_back(static_cast<int>(n));
      }
    }
    std::vector<bool> visited(model_.nodes.size(), false);
    bool any_bounds = false;
    std::function<void(int, const glm::mat4&)> visit = [&](int index, const glm::mat4& parent) {
      if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size()) fail("a scene refers to node " + std::to_string(index) + ", which does not exist");
      if (visited[static_cast<std::size_t>(index)]) fail("node " + std::to_string(index) + " appears twice in the hierarchy (a cycle?)");
      visited[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
      const glm::mat4 world = parent * local_matrix(node);
      if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= asset.meshes.size()) fail("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) + ", which does not exist");
        SceneInstance instance;
        instance.mesh = static_cast<std::uint32_t>(node.mesh);
        glm::vec3 skew;
        glm::vec4 perspective;
        glm::decompose(world, instance.transform.scale, instance.transform.rotation, instance.transform.position, skew, perspective);
        result_.instances.push_back(instance);
        for (const Primitive& p : asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
          for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? p.bounds_max.x : p.bounds_min.x, (corner & 2) ? p.bounds_max.y : p.bounds_min.y,
                                  (corner & 4) ? p.bounds_max.z : p.bounds_min.z);
            const glm::vec3 w(world * glm::vec4(local, 1.0f));
            result_.bounds_min = any_bounds ? glm::min(result_.bounds_min, w) : w;
            result_.bounds_max = any_bounds ? glm::max(result_.bounds_max, w) : w;
            any_bounds = true;
          }
        }
      }
      const auto light = node.extensions.find("KHR_lights_punctual");
      if (light != node.extensions.end() && light->second.Has("light")) add_light(light->second.Get("light").GetNumberAsInt(), world);
      for (int child : node.children) visit(child, world);
    };
    for (int root : roots) visit(root, glm::mat4(1.0f));
  }

  void add_light(int index, const glm::mat4& world) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.lights.size()) {
      warn("a node refers to light " + std::to_string(index) + ", which does not exist; it is skipped");
      return;
    }
    const tinygltf::Light& src = model_.lights[static_cast<std::size_t>(index)];
    SceneLight light;
    light.position = glm::vec3(world[3]);
    light.direction = glm::normalize(glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)));
    if (src.color.size() == 3) light.color = glm::vec3(glm::make_vec3(src.color.data()));
    light.intensity = static_cast<float>(src.intensity) / kLumensPerWatt;
    if (src.range > 0.0) light.radius = static_cast<float>(src.range);
    if (src.type == "directional") {
      light.kind = LightKind::Directional;
    } else if (src.type == "spot") {
      light.kind = LightKind::Spot;
      light.inner_cone = static_cast<float>(src.spot.innerConeAngle);
      light.outer_cone = static_cast<float>(src.spot.outerConeAngle);
    } else if (src.type != "point") {
      warn("light " + std::to_string(index) + " has the unknown type '" + src.type + "' and is skipped");
      return;
    }
    // A light that would poison every pixel it reaches (NaN, infinity) or give
    // nothing (zero, negative) is dropped; the rest of the model still loads.
    const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    const std::string name = "light " + std::to_string(index) + (src.name.empty() ? "" : " '" + src.name + "'");
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
  tinygltf::Model model_;
  std::vector<ByteRange> views_;
  std::vector<std::vector<std::uint8_t>> decoded_;
  std::vector<PendingSlot> pending_slots_;
  std::optional<std::uint32_t> default_material_;
  SkippedTriangles non_finite_, zero_area_;
  std::size_t triangles_read_ = 0;
  GltfImport result_;
};

}  // namespace

const std::vector<std::string>& supported_gltf_extensions() {
  static const std::vector<std::string> kSupported{"KHR_materials_emissive_strength", "KHR_texture_transform",
                                                   "KHR_lights_punctual", "KHR_mesh_quantization",
                                                   "EXT_meshopt_compression"};
  return kSupported;
}

GltfImport import_gltf(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  return Importer(path, assets, options).run();
}

}  // namespace atrium::assets
