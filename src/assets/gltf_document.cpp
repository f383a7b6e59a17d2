#include "assets/gltf_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace atrium::assets::gltf {
namespace {

// The largest byte length or offset a file may state: what this platform's
// size_t holds (32 bits in the WebAssembly build), less two bits, so that the
// sums the range checks form (offset + length, offset + stride * count) cannot
// wrap around. A larger value is refused, never truncated.
constexpr std::uint64_t kMaxBytes = std::numeric_limits<std::size_t>::max() / 4;

namespace fs = std::filesystem;

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr std::uint32_t kChunkBinary = 0x004E4942;   // "BIN\0"

int base64_value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;
  if (c == '/' || c == '_') return 63;
  return -1;
}

// The size a base64 text decodes to (without decoding it).
std::size_t base64_size(std::string_view text) {
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  return text.size() / 4 * 3 + (text.size() % 4 >= 2 ? text.size() % 4 - 1 : 0);
}

bool base64_decode(std::string_view text, std::vector<std::uint8_t>& out) {
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  out.clear();
  out.reserve(base64_size(text));
  std::uint32_t bits = 0;
  int held = 0;
  for (unsigned char c : text) {
    const int v = base64_value(c);
    if (v < 0) return false;
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    held += 6;
    if (held >= 8) {
      held -= 8;
      out.push_back(static_cast<std::uint8_t>((bits >> held) & 0xff));
    }
  }
  return text.size() % 4 != 1;
}

// "data:[<media type>][;base64],<data>": the payload after the comma, or
// nullopt when `uri` is no base64 data URI.
std::optional<std::string_view> data_uri_payload(std::string_view uri) {
  if (uri.substr(0, 5) != "data:") return std::nullopt;
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  const std::string_view header = uri.substr(0, comma);
  if (header.size() < 7 || header.substr(header.size() - 7) != ";base64") return std::nullopt;
  return uri.substr(comma + 1);
}

std::string percent_decode(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// The file a relative URI names; empty when it names something that is no
// local file (http:, ...).
fs::path uri_path(const fs::path& gltf, const std::string& uri) {
  const std::size_t colon = uri.find(':');
  const std::size_t slash = uri.find('/');
  if (colon != std::string::npos && colon > 1 && (slash == std::string::npos || colon < slash)) {
    if (uri.rfind("file://", 0) == 0) return fs::path(percent_decode(uri.substr(7)));
    return {};
  }
  const fs::path relative(percent_decode(uri));
  return relative.is_absolute() ? relative : gltf.parent_path() / relative;
}

// Reads the first `size` bytes of a regular file, or fails with a message.
bool read_file_prefix(const fs::path& path, std::size_t size, std::vector<std::uint8_t>& out, std::string& error) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    error = "the file " + path.string() + " is missing or unreadable";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  out.resize(size);
  in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size));
  if (static_cast<std::size_t>(in.gcount()) != size) {
    error = "the file " + path.string() + " cannot be read";
    return false;
  }
  return true;
}

class DocumentReader {
 public:
  DocumentReader(const fs::path& path, const MemoryBudget& budget) : r_(path.string()), budget_(budget) { doc_.path = path; }

  Document read() {
    std::error_code ec;
    if (!fs::is_regular_file(doc_.path, ec)) refuse("no such file");
    const std::uintmax_t file_size = fs::file_size(doc_.path, ec);
    if (ec) refuse("cannot be read");
    std::ifstream in(doc_.path, std::ios::binary);
    std::uint32_t magic = 0;
    in.read(reinterpret_cast<char*>(&magic), 4);
    const bool binary = in.gcount() == 4 && magic == kGlbMagic;
    in.seekg(0);
    if (binary) read_glb(in, file_size);
    else read_json_text(in, file_size);
    parse();
    return std::move(doc_);
  }

 private:
  // The file as a whole is refused ("box.glb: is a truncated binary glTF").
  [[noreturn]] void refuse(const std::string& problem) const { throw ImportError(r_.file() + ": " + problem); }
  [[noreturn]] void fail(const JsonPointer& where, const std::string& problem) const { r_.fail(where, problem); }
  void warn(const JsonPointer& where, const std::string& problem) { doc_.warnings.push_back(r_.file() + ": " + where.str() + ": " + problem); }

  void parse_json(const char* text, std::size_t size) {
    root_ = r_.parse(std::string_view(text, size));
    if (!root_.is_object()) refuse("is not a glTF file (its JSON is not an object)");
  }

  void read_json_text(std::ifstream& in, std::uintmax_t file_size) {
    budget_.require(static_cast<std::size_t>(file_size) * 8, "the JSON text (" + format_bytes(static_cast<double>(file_size)) + ")");
    std::string text(static_cast<std::size_t>(file_size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(file_size));
    parse_json(text.data(), text.size());
  }

  // Binary glTF: a 12-byte header, a JSON chunk, then an optional BIN chunk.
  void read_glb(std::ifstream& in, std::uintmax_t file_size) {
    std::uint32_t header[3] = {};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (in.gcount() != sizeof header) refuse("is a truncated binary glTF (no 12-byte header)");
    if (header[1] != 2) refuse("is binary glTF version " + std::to_string(header[1]) + "; Atrium reads version 2");
    if (header[2] > file_size) {
      refuse("declares a length of " + with_commas(header[2]) + " bytes, but the file has " + with_commas(file_size) + " (truncated?)");
    }
    std::size_t offset = 12;
    bool json = false;
    while (offset + 8 <= header[2]) {
      std::uint32_t chunk[2] = {};
      in.seekg(static_cast<std::streamoff>(offset));
      in.read(reinterpret_cast<char*>(chunk), sizeof chunk);
      const std::size_t length = chunk[0];
      if (length > header[2] - offset - 8) {
        refuse("has a chunk at byte " + with_commas(offset) + " of " + with_commas(length) + " bytes, past the end of the file");
      }
      if (!json) {
        if (chunk[1] != kChunkJson) refuse("is binary glTF whose first chunk is not JSON");
        budget_.require(length * 8, "the JSON chunk (" + format_bytes(static_cast<double>(length)) + ")");
        std::string text(length, '\0');
        in.read(text.data(), static_cast<std::streamsize>(length));
        parse_json(text.data(), text.size());
        json = true;
      } else if (chunk[1] == kChunkBinary && !binary_chunk_) {
        budget_.require(length, "the BIN chunk");
        binary_chunk_.emplace(length);
        in.read(reinterpret_cast<char*>(binary_chunk_->data()), static_cast<std::streamsize>(length));
        if (static_cast<std::size_t>(in.gcount()) != length) refuse("cannot read its BIN chunk");
      }
      offset += 8 + ((length + 3) & ~std::size_t{3});
    }
    if (!json) refuse("is binary glTF without a JSON chunk");
  }

  void parse() {
    const Json& root = root_;
    const JsonPointer top;
    // Every glTF names its version in /asset/version; JSON without it is some
    // other document saved as .gltf, refused rather than shown as an empty scene.
    // (An empty version, as tinygltf's issue-416 case writes, is let through.)
    const Json* asset = r_.find(root, "asset");
    if (!asset || !r_.find(*asset, "version")) {
      refuse("is not a glTF file: its JSON has no /asset/version (every glTF names its version there)");
    }
    const std::string version = r_.string(*r_.find(*asset, "version"), top / "asset" / "version");
    if (!version.empty() && version[0] != '2') refuse("is glTF version " + version + "; Atrium reads glTF 2.0");
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
      auto& out = std::string(key) == "extensionsUsed" ? doc_.extensions_used : doc_.extensions_required;
      const Json& names = r_.array_or_empty(root, top, key);
      for (std::size_t i = 0; i < names.size(); ++i) out.push_back(r_.string(names[i], top / key / i));
    }
    // The sizes of every array first, so that references can be checked as they are read.
    for (const char* key : {"buffers", "bufferViews", "accessors", "meshes", "materials", "textures", "images", "samplers", "nodes", "scenes"}) {
      counts_[key] = r_.array_or_empty(root, top, key).size();
    }
    const Json extensions = r_.object_or_empty(root, top, "extensions");
    if (extensions.contains("KHR_lights_punctual")) {
      read_lights(r_.object(extensions["KHR_lights_punctual"], top / "extensions" / "KHR_lights_punctual"));
    }
    read_buffers();
    read_buffer_views();
    read_accessors();
    read_meshes();
    read_materials();
    read_textures();
    read_images();
    read_samplers();
    read_nodes();
    read_scenes();
  }

  std::size_t count(const char* key) const { return counts_.at(key); }
  // A reference into a top-level array; -1 when absent and not required.
  int index(const Json& object, const JsonPointer& where, const char* key, const char* target, bool required = false) const {
    const Json* value = r_.find(object, key);
    if (!value && required) r_.required(object, where, key);
    return value ? static_cast<int>(r_.index(*value, where / key, count(target), JsonPointer() / target)) : -1;
  }
  std::size_t required_index(const Json& object, const JsonPointer& where, const char* key, const char* target) const {
    return static_cast<std::size_t>(index(object, where, key, target, true));
  }

  // --- buffers ---------------------------------------------------------------

  void read_buffers() {
    const Json& buffers = r_.array_or_empty(root_, {}, "buffers");
    doc_.buffers.resize(buffers.size());
    for (std::size_t b = 0; b < buffers.size(); ++b) {
      const JsonPointer where = element("buffers", b);
      const Json& j = r_.object(buffers[b], where);
      Buffer& buffer = doc_.buffers[b];
      buffer.byte_length = r_.whole(r_.required(j, where, "byteLength"), where / "byteLength", 0, kMaxBytes);
      const Json ext = r_.object_or_empty(j, where, "extensions");
      const bool fallback = ext.contains("EXT_meshopt_compression") &&
                            r_.boolean_or(r_.object(ext["EXT_meshopt_compression"], where / "extensions" / "EXT_meshopt_compression"),
                                          where / "extensions" / "EXT_meshopt_compression", "fallback", false);
      if (!r_.find(j, "uri")) {
        if (b == 0 && binary_chunk_) {
          if (buffer.byte_length > binary_chunk_->size()) {
            fail(where, "declares byteLength " + with_commas(buffer.byte_length) + ", but the BIN chunk holds " +
                            with_commas(binary_chunk_->size()) + " bytes");
          }
          buffer.data = std::move(*binary_chunk_);
          buffer.data.resize(buffer.byte_length);
          continue;
        }
        if (fallback) {
          buffer.fallback_only = true;
          continue;
        }
        if (buffer.byte_length == 0) continue;
        fail(where, "has no uri and is not the BIN chunk of a binary glTF, so it holds no data");
      }
      const std::string uri = r_.string(j["uri"], where / "uri");
      if (const auto payload = data_uri_payload(uri)) {
        if (base64_size(*payload) < buffer.byte_length) {
          fail(where, "declares byteLength " + with_commas(buffer.byte_length) + ", but its data URI holds " +
                          with_commas(base64_size(*payload)) + " bytes");
        }
        budget_.require(base64_size(*payload), where.str() + " (data URI)");
        if (!base64_decode(*payload, buffer.data)) fail(where, "has a data URI that is not valid base64");
        buffer.data.resize(buffer.byte_length);
        continue;
      }
      if (uri.rfind("data:", 0) == 0) fail(where, "has a data URI that is not base64 (glTF requires base64)");
      const fs::path file = uri_path(doc_.path, uri);
      if (file.empty()) fail(where, "refers to " + uri + ", which is not a local file (Atrium downloads nothing)");
      std::error_code ec;
      if (!fs::is_regular_file(file, ec)) fail(where, "refers to " + file.string() + ", which does not exist");
      const std::uintmax_t size = fs::file_size(file, ec);
      if (ec || size < buffer.byte_length) {
        fail(where, "declares byteLength " + with_commas(buffer.byte_length) + ", but " + file.filename().string() + " has " +
                        with_commas(ec ? 0 : size) + " bytes");
      }
      budget_.require(buffer.byte_length, where.str() + " (" + file.filename().string() + ")");
      std::string error;
      if (!read_file_prefix(file, buffer.byte_length, buffer.data, error)) fail(where, error);
    }
  }

  void read_buffer_views() {
    const Json& views = r_.array_or_empty(root_, {}, "bufferViews");
    doc_.buffer_views.resize(views.size());
    for (std::size_t v = 0; v < views.size(); ++v) {
      const JsonPointer where = element("bufferViews", v);
      const Json& j = r_.object(views[v], where);
      BufferView& view = doc_.buffer_views[v];
      view.buffer = required_index(j, where, "buffer", "buffers");
      view.byte_offset = r_.whole_or(j, where, "byteOffset", 0, kMaxBytes, 0);
      view.byte_length = r_.whole(r_.required(j, where, "byteLength"), where / "byteLength", 1, kMaxBytes);
      if (r_.find(j, "byteStride")) {
        view.byte_stride = r_.whole(j["byteStride"], where / "byteStride", 4, 252);
        if (view.byte_stride % 4 != 0) fail(where / "byteStride", "expected a multiple of 4, got " + std::to_string(view.byte_stride));
      }
      const Buffer& buffer = doc_.buffers[view.buffer];
      if (view.byte_offset > buffer.byte_length || view.byte_length > buffer.byte_length - view.byte_offset) {
        fail(where, "covers bytes " + with_commas(view.byte_offset) + " to " + with_commas(view.byte_offset + view.byte_length) + " of " +
                        element("buffers", view.buffer).str() + ", which has " + with_commas(buffer.byte_length));
      }
      const Json ext = r_.object_or_empty(j, where, "extensions");
      if (ext.contains("EXT_meshopt_compression")) {
        const JsonPointer mw = where / "extensions" / "EXT_meshopt_compression";
        view.meshopt = read_meshopt(r_.object(ext["EXT_meshopt_compression"], mw), mw, view);
      } else if (buffer.fallback_only) {
        fail(where, "points into " + element("buffers", view.buffer).str() +
                        ", which holds no data (an EXT_meshopt_compression fallback), and is not compressed");
      }
    }
  }

  MeshoptSource read_meshopt(const Json& j, const JsonPointer& where, const BufferView& view) {
    MeshoptSource m;
    m.buffer = required_index(j, where, "buffer", "buffers");
    m.byte_offset = r_.whole_or(j, where, "byteOffset", 0, kMaxBytes, 0);
    m.byte_length = r_.whole(r_.required(j, where, "byteLength"), where / "byteLength", 1, kMaxBytes);
    m.byte_stride = r_.whole(r_.required(j, where, "byteStride"), where / "byteStride", 1, 256);
    m.count = r_.whole(r_.required(j, where, "count"), where / "count", 1, std::numeric_limits<std::uint32_t>::max());
    const std::string mode = r_.string(r_.required(j, where, "mode"), where / "mode");
    const std::string filter = r_.string_or(j, where, "filter", "NONE");
    if (mode == "ATTRIBUTES") m.mode = MeshoptSource::Mode::Attributes;
    else if (mode == "TRIANGLES") m.mode = MeshoptSource::Mode::Triangles;
    else if (mode == "INDICES") m.mode = MeshoptSource::Mode::Indices;
    else fail(where / "mode", "expected ATTRIBUTES, TRIANGLES or INDICES, got \"" + mode + "\"");
    if (filter == "OCTAHEDRAL") m.filter = MeshoptSource::Filter::Octahedral;
    else if (filter == "QUATERNION") m.filter = MeshoptSource::Filter::Quaternion;
    else if (filter == "EXPONENTIAL") m.filter = MeshoptSource::Filter::Exponential;
    else if (filter != "NONE") fail(where / "filter", "expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL, got \"" + filter + "\"");
    // The decoders' own preconditions (meshoptimizer asserts them).
    const std::size_t s = m.byte_stride;
    const std::string got = ", got " + std::to_string(s);
    if (m.mode == MeshoptSource::Mode::Attributes && s % 4 != 0) fail(where / "byteStride", "expected a multiple of 4 for ATTRIBUTES" + got);
    if (m.mode != MeshoptSource::Mode::Attributes && s != 2 && s != 4) fail(where / "byteStride", "expected 2 or 4 for index modes" + got);
    if (m.mode == MeshoptSource::Mode::Triangles && m.count % 3 != 0) {
      fail(where / "count", "expected a multiple of 3 for TRIANGLES, got " + with_commas(m.count));
    }
    if (m.filter != MeshoptSource::Filter::None && m.mode != MeshoptSource::Mode::Attributes) {
      fail(where / "filter", "expected NONE (only ATTRIBUTES take a filter), got \"" + filter + "\"");
    }
    if (m.filter == MeshoptSource::Filter::Octahedral && s != 4 && s != 8) fail(where / "byteStride", "expected 4 or 8 for OCTAHEDRAL" + got);
    if (m.filter == MeshoptSource::Filter::Quaternion && s != 8) fail(where / "byteStride", "expected 8 for QUATERNION" + got);
    if (m.count * m.byte_stride != view.byte_length) {
      fail(where, "decodes to " + with_commas(m.count) + " x " + std::to_string(s) + " bytes, but the bufferView's byteLength is " +
                      with_commas(view.byte_length));
    }
    const Buffer& source = doc_.buffers[m.buffer];
    if (source.fallback_only) fail(where / "buffer", "refers to the fallback buffer, which holds no data");
    if (m.byte_offset > source.byte_length || m.byte_length > source.byte_length - m.byte_offset) {
      fail(where, "reads bytes " + with_commas(m.byte_offset) + " to " + with_commas(m.byte_offset + m.byte_length) + " of " +
                      element("buffers", m.buffer).str() + ", which has " + with_commas(source.byte_length));
    }
    return m;
  }

  // --- accessors -------------------------------------------------------------

  void read_accessors() {
    const Json& accessors = r_.array_or_empty(root_, {}, "accessors");
    doc_.accessors.resize(accessors.size());
    constexpr std::size_t kMax = std::numeric_limits<std::uint32_t>::max();
    for (std::size_t i = 0; i < accessors.size(); ++i) {
      const JsonPointer where = element("accessors", i);
      const Json& j = r_.object(accessors[i], where);
      Accessor& a = doc_.accessors[i];
      a.buffer_view = index(j, where, "bufferView", "bufferViews");
      a.byte_offset = r_.whole_or(j, where, "byteOffset", 0, kMaxBytes, 0);
      a.component_type = static_cast<int>(r_.whole(r_.required(j, where, "componentType"), where / "componentType", 0, 100000));
      if (component_size(a.component_type) == 0) {
        fail(where / "componentType", "expected a glTF component type (5120 to 5126), got " + std::to_string(a.component_type));
      }
      a.type = r_.string(r_.required(j, where, "type"), where / "type");
      static const std::map<std::string, int> kComponents{{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                          {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
      const auto type = kComponents.find(a.type);
      if (type == kComponents.end()) fail(where / "type", "expected a glTF accessor type (SCALAR, VEC2 ... MAT4), got \"" + a.type + "\"");
      a.components = type->second;
      a.normalized = r_.boolean_or(j, where, "normalized", false);
      a.count = r_.whole(r_.required(j, where, "count"), where / "count", 1, kMax);
      if (a.buffer_view >= 0) check_range(where, static_cast<std::size_t>(a.buffer_view), a.byte_offset, a.count, a.element_size());
      if (const Json* sparse = r_.find(j, "sparse")) a.sparse = read_sparse(r_.object(*sparse, where / "sparse"), where / "sparse", a);
    }
  }

  // `count` elements of `element_size` bytes from `byte_offset` in a bufferView.
  void check_range(const JsonPointer& where, std::size_t view_index, std::size_t byte_offset, std::size_t count, std::size_t element_size) {
    const BufferView& view = doc_.buffer_views[view_index];
    const std::size_t stride = view.byte_stride ? view.byte_stride : element_size;
    if (view.byte_stride && view.byte_stride < element_size) {
      fail(where, "has " + std::to_string(element_size) + "-byte elements, wider than the byteStride " + std::to_string(view.byte_stride) +
                      " of " + element("bufferViews", view_index).str());
    }
    // (count - 1) * stride + element_size bytes from byte_offset, without overflow.
    const bool fits = byte_offset <= view.byte_length && element_size <= view.byte_length - byte_offset &&
                      count - 1 <= (view.byte_length - byte_offset - element_size) / stride;
    if (!fits) {
      fail(where, "reads " + with_commas(count) + " elements of " + std::to_string(element_size) + " bytes from byte " +
                      with_commas(byte_offset) + " of " + element("bufferViews", view_index).str() + ", which holds " +
                      with_commas(view.byte_length) + " bytes");
    }
  }

  Accessor::Sparse read_sparse(const Json& j, const JsonPointer& where, const Accessor& a) {
    Accessor::Sparse s;
    constexpr std::size_t kMax = std::numeric_limits<std::uint32_t>::max();
    s.count = r_.whole(r_.required(j, where, "count"), where / "count", 1, a.count);
    const JsonPointer iw = where / "indices", vw = where / "values";
    const Json& indices = r_.object(r_.required(j, where, "indices"), iw);
    const Json& values = r_.object(r_.required(j, where, "values"), vw);
    s.indices_view = required_index(indices, iw, "bufferView", "bufferViews");
    s.indices_offset = r_.whole_or(indices, iw, "byteOffset", 0, kMax, 0);
    s.indices_component_type = static_cast<int>(r_.whole(r_.required(indices, iw, "componentType"), iw / "componentType", 0, 100000));
    if (s.indices_component_type != kUnsignedByte && s.indices_component_type != kUnsignedShort && s.indices_component_type != kUnsignedInt) {
      fail(iw / "componentType", "expected an unsigned integer type (5121, 5123 or 5125), got " + std::to_string(s.indices_component_type));
    }
    s.values_view = required_index(values, vw, "bufferView", "bufferViews");
    s.values_offset = r_.whole_or(values, vw, "byteOffset", 0, kMax, 0);
    // Sparse data is tightly packed: a bufferView stride would not apply.
    for (const auto& [view, offset, size, what] :
         {std::tuple{s.indices_view, s.indices_offset, component_size(s.indices_component_type), iw},
          std::tuple{s.values_view, s.values_offset, a.element_size(), vw}}) {
      const BufferView& v = doc_.buffer_views[view];
      if (offset > v.byte_length || s.count > (v.byte_length - offset) / size) {
        fail(what, "reads " + with_commas(s.count) + " elements of " + std::to_string(size) + " bytes from byte " + with_commas(offset) +
                       " of " + element("bufferViews", view).str() + ", which holds " + with_commas(v.byte_length) + " bytes");
      }
    }
    return s;
  }

  // --- meshes ----------------------------------------------------------------

  void read_meshes() {
    const Json& meshes = r_.array_or_empty(root_, {}, "meshes");
    doc_.meshes.resize(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const JsonPointer where = element("meshes", m);
      const Json& j = r_.object(meshes[m], where);
      Mesh& mesh = doc_.meshes[m];
      mesh.name = r_.string_or(j, where, "name", "");
      const Json& primitives = r_.array_or_empty(j, where, "primitives");
      for (std::size_t p = 0; p < primitives.size(); ++p) {
        const JsonPointer pw = where / "primitives" / p;
        const Json& pj = r_.object(primitives[p], pw);
        Primitive primitive;
        for (const auto& [semantic, value] : r_.object_or_empty(pj, pw, "attributes").items()) {
          primitive.attributes[semantic] =
              static_cast<int>(r_.index(value, pw / "attributes" / semantic, count("accessors"), JsonPointer() / "accessors"));
        }
        primitive.indices = index(pj, pw, "indices", "accessors");
        primitive.material = index(pj, pw, "material", "materials");
        primitive.mode = static_cast<int>(r_.whole_or(pj, pw, "mode", 0, 6, 4));
        const Json ext = r_.object_or_empty(pj, pw, "extensions");
        if (ext.contains("KHR_draco_mesh_compression")) {
          const JsonPointer dw = pw / "extensions" / "KHR_draco_mesh_compression";
          const Json& dj = r_.object(ext["KHR_draco_mesh_compression"], dw);
          DracoPrimitive draco;
          draco.buffer_view = required_index(dj, dw, "bufferView", "bufferViews");
          for (const auto& [semantic, value] : r_.object(r_.required(dj, dw, "attributes"), dw / "attributes").items()) {
            draco.attributes[semantic] = static_cast<int>(r_.whole(value, dw / "attributes" / semantic, 0, 1u << 20));
          }
          primitive.draco = std::move(draco);
        }
        mesh.primitives.push_back(std::move(primitive));
      }
    }
  }

  // --- materials, textures, images, samplers ----------------------------------

  TextureInfo read_texture_info(const Json& material, const char* key, const JsonPointer& where, const char* scale_key) {
    TextureInfo info;
    const Json* j = r_.find(material, key);
    if (!j) return info;
    const JsonPointer tw = where / key;
    r_.object(*j, tw);
    info.index = index(*j, tw, "index", "textures", true);
    info.tex_coord = static_cast<int>(r_.whole_or(*j, tw, "texCoord", 0, 31, 0));
    if (scale_key) info.scale = r_.number_or(*j, tw, scale_key, 1.0);
    info.extensions = r_.object_or_empty(*j, tw, "extensions");
    return info;
  }

  void read_materials() {
    const Json& materials = r_.array_or_empty(root_, {}, "materials");
    doc_.materials.resize(materials.size());
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const JsonPointer where = element("materials", i);
      const Json& j = r_.object(materials[i], where);
      Material& m = doc_.materials[i];
      m.name = r_.string_or(j, where, "name", "");
      if (const Json* pbr = r_.find(j, "pbrMetallicRoughness")) {
        const JsonPointer pw = where / "pbrMetallicRoughness";
        r_.object(*pbr, pw);
        m.base_color_factor = r_.numbers_or<4>(*pbr, pw, "baseColorFactor", m.base_color_factor);
        m.metallic_factor = r_.number_or(*pbr, pw, "metallicFactor", 1.0);
        m.roughness_factor = r_.number_or(*pbr, pw, "roughnessFactor", 1.0);
        m.base_color = read_texture_info(*pbr, "baseColorTexture", pw, nullptr);
        m.metallic_roughness = read_texture_info(*pbr, "metallicRoughnessTexture", pw, nullptr);
      }
      m.normal = read_texture_info(j, "normalTexture", where, "scale");
      m.occlusion = read_texture_info(j, "occlusionTexture", where, "strength");
      m.emissive = read_texture_info(j, "emissiveTexture", where, nullptr);
      m.emissive_factor = r_.numbers_or<3>(j, where, "emissiveFactor", m.emissive_factor);
      m.alpha_mode = r_.string_or(j, where, "alphaMode", "OPAQUE");
      if (m.alpha_mode != "OPAQUE" && m.alpha_mode != "MASK" && m.alpha_mode != "BLEND") {
        warn(where / "alphaMode", "expected OPAQUE, MASK or BLEND, got \"" + m.alpha_mode + "\"; it is drawn opaque");
        m.alpha_mode = "OPAQUE";
      }
      m.alpha_cutoff = r_.number_or(j, where, "alphaCutoff", 0.5);
      m.double_sided = r_.boolean_or(j, where, "doubleSided", false);
      m.extensions = r_.object_or_empty(j, where, "extensions");
    }
  }

  void read_textures() {
    const Json& textures = r_.array_or_empty(root_, {}, "textures");
    doc_.textures.resize(textures.size());
    for (std::size_t i = 0; i < textures.size(); ++i) {
      const JsonPointer where = element("textures", i);
      const Json& j = r_.object(textures[i], where);
      doc_.textures[i].sampler = index(j, where, "sampler", "samplers");
      doc_.textures[i].source = index(j, where, "source", "images");
      doc_.textures[i].extensions = r_.object_or_empty(j, where, "extensions");
      const auto dds = doc_.textures[i].extensions.find("MSFT_texture_dds");
      if (dds != doc_.textures[i].extensions.end()) {
        const JsonPointer dds_where = where / "extensions" / "MSFT_texture_dds";
        doc_.textures[i].dds_source = index(r_.object(*dds, dds_where), dds_where, "source", "images");
      }
    }
  }

  void read_images() {
    const Json& images = r_.array_or_empty(root_, {}, "images");
    doc_.images.resize(images.size());
    for (std::size_t i = 0; i < images.size(); ++i) {
      const JsonPointer where = element("images", i);
      const Json& j = r_.object(images[i], where);
      Image& image = doc_.images[i];
      image.name = r_.string_or(j, where, "name", "");
      image.uri = r_.string_or(j, where, "uri", "");
      image.buffer_view = index(j, where, "bufferView", "bufferViews");
      image.mime_type = r_.string_or(j, where, "mimeType", "");
    }
  }

  void read_samplers() {
    const Json& samplers = r_.array_or_empty(root_, {}, "samplers");
    doc_.samplers.resize(samplers.size());
    for (std::size_t i = 0; i < samplers.size(); ++i) {
      const JsonPointer where = element("samplers", i);
      const Json& j = r_.object(samplers[i], where);
      Sampler& s = doc_.samplers[i];
      auto code = [&](const char* key, std::initializer_list<int> allowed, int fallback) {
        const Json* value = r_.find(j, key);
        if (!value) return fallback;
        const int code = static_cast<int>(r_.whole(*value, where / key, 0, 100000));
        if (std::find(allowed.begin(), allowed.end(), code) == allowed.end()) {
          warn(where / key, "expected a glTF sampler value, got " + std::to_string(code) + "; the default is used");
          return fallback;
        }
        return code;
      };
      s.mag_filter = code("magFilter", {9728, 9729}, -1);
      s.min_filter = code("minFilter", {9728, 9729, 9984, 9985, 9986, 9987}, -1);
      s.wrap_s = code("wrapS", {33071, 33648, 10497}, 10497);
      s.wrap_t = code("wrapT", {33071, 33648, 10497}, 10497);
    }
  }

  // --- nodes, scenes, lights ---------------------------------------------------

  void read_nodes() {
    const Json& nodes = r_.array_or_empty(root_, {}, "nodes");
    doc_.nodes.resize(nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      const JsonPointer where = element("nodes", n);
      const Json& j = r_.object(nodes[n], where);
      Node& node = doc_.nodes[n];
      node.name = r_.string_or(j, where, "name", "");
      node.mesh = index(j, where, "mesh", "meshes");
      const Json& children = r_.array_or_empty(j, where, "children");
      for (std::size_t c = 0; c < children.size(); ++c) {
        node.children.push_back(static_cast<int>(r_.index(children[c], where / "children" / c, count("nodes"), JsonPointer() / "nodes")));
      }
      if (const Json* matrix = r_.find(j, "matrix")) {
        const auto m = r_.numbers<16>(*matrix, where / "matrix");
        for (int c = 0; c < 16; ++c) glm::value_ptr(node.local)[c] = static_cast<float>(m[static_cast<std::size_t>(c)]);
      } else {
        const auto t = r_.numbers_or<3>(j, where, "translation", {0.0, 0.0, 0.0});
        const auto q = r_.numbers_or<4>(j, where, "rotation", {0.0, 0.0, 0.0, 1.0});
        const auto s = r_.numbers_or<3>(j, where, "scale", {1.0, 1.0, 1.0});
        const glm::quat rotation(static_cast<float>(q[3]), static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]));
        node.local = glm::translate(glm::mat4(1.0f), glm::vec3(t[0], t[1], t[2])) * glm::mat4_cast(rotation) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(s[0], s[1], s[2]));
      }
      const Json ext = r_.object_or_empty(j, where, "extensions");
      if (ext.contains("KHR_lights_punctual")) {
        const JsonPointer lw = where / "extensions" / "KHR_lights_punctual";
        const Json& lj = r_.object(ext["KHR_lights_punctual"], lw);
        node.light = static_cast<int>(r_.index(r_.required(lj, lw, "light"), lw / "light", doc_.lights.size(),
                                               JsonPointer() / "extensions" / "KHR_lights_punctual" / "lights"));
      }
      if (ext.contains("EXT_mesh_gpu_instancing")) {
        const JsonPointer iw = where / "extensions" / "EXT_mesh_gpu_instancing";
        const Json& ij = r_.object(ext["EXT_mesh_gpu_instancing"], iw);
        Node::Instancing instancing;
        for (const auto& [semantic, value] : r_.object(r_.required(ij, iw, "attributes"), iw / "attributes").items()) {
          const int accessor =
              static_cast<int>(r_.index(value, iw / "attributes" / semantic, count("accessors"), JsonPointer() / "accessors"));
          if (semantic == "TRANSLATION") instancing.translation = accessor;
          else if (semantic == "ROTATION") instancing.rotation = accessor;
          else if (semantic == "SCALE") instancing.scale = accessor;
        }
        node.instancing = instancing;
      }
    }
  }

  void read_scenes() {
    const Json& scenes = r_.array_or_empty(root_, {}, "scenes");
    for (std::size_t s = 0; s < scenes.size(); ++s) {
      const JsonPointer where = element("scenes", s);
      const Json& j = r_.object(scenes[s], where);
      std::vector<int> roots;
      const Json& nodes = r_.array_or_empty(j, where, "nodes");
      for (std::size_t n = 0; n < nodes.size(); ++n) {
        roots.push_back(static_cast<int>(r_.index(nodes[n], where / "nodes" / n, count("nodes"), JsonPointer() / "nodes")));
      }
      doc_.scenes.push_back(std::move(roots));
    }
    doc_.scene = index(root_, {}, "scene", "scenes");
  }

  void read_lights(const Json& extension) {
    const JsonPointer list = JsonPointer() / "extensions" / "KHR_lights_punctual";
    const Json& lights = r_.array_or_empty(extension, list, "lights");
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const JsonPointer where = list / "lights" / i;
      const Json& j = r_.object(lights[i], where);
      Light light;
      light.name = r_.string_or(j, where, "name", "");
      light.type = r_.string_or(j, where, "type", "");
      light.color = r_.numbers_or<3>(j, where, "color", light.color);
      light.intensity = r_.number_or(j, where, "intensity", 1.0);
      light.range = r_.number_or(j, where, "range", 0.0);
      if (const Json* spot = r_.find(j, "spot")) {
        const JsonPointer sw = where / "spot";
        r_.object(*spot, sw);
        light.inner_cone = r_.number_or(*spot, sw, "innerConeAngle", 0.0);
        light.outer_cone = r_.number_or(*spot, sw, "outerConeAngle", light.outer_cone);
      }
      doc_.lights.push_back(light);
    }
  }

  JsonReader r_;
  const MemoryBudget& budget_;
  Document doc_;
  Json root_;
  std::optional<std::vector<std::uint8_t>> binary_chunk_;
  std::map<std::string, std::size_t> counts_;
};

}  // namespace

std::size_t component_size(int component_type) {
  switch (component_type) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
  }
}

Document read_document(const std::filesystem::path& path, const MemoryBudget& budget) {
  try {
    return DocumentReader(path, budget).read();
  } catch (const JsonError& e) {
    throw ImportError(e.what());
  }
}

std::string image_uri_problem(const Document& document, const std::string& uri) {
  if (const auto payload = data_uri_payload(uri)) {
    std::vector<std::uint8_t> ignored;
    return base64_decode(*payload, ignored) ? "" : "its data URI is not valid base64";
  }
  if (uri.rfind("data:", 0) == 0) return "its data URI is not base64";
  const fs::path file = uri_path(document.path, uri);
  if (file.empty()) return "it is not a local file (Atrium downloads nothing)";
  std::error_code ec;
  return fs::is_regular_file(file, ec) ? "" : "the file is missing or unreadable";
}

std::vector<std::uint8_t> read_image_uri(const Document& document, const std::string& uri, const MemoryBudget& budget, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (const auto payload = data_uri_payload(uri)) {
    if (base64_size(*payload) > budget.limit()) {
      error = "its data URI needs " + format_bytes(static_cast<double>(base64_size(*payload)));
      return {};
    }
    if (!base64_decode(*payload, bytes)) error = "its data URI is not valid base64";
    return bytes;
  }
  if (uri.rfind("data:", 0) == 0) {
    error = "its data URI is not base64";
    return {};
  }
  const fs::path file = uri_path(document.path, uri);
  if (file.empty()) {
    error = "it is not a local file (Atrium downloads nothing)";
    return {};
  }
  std::error_code ec;
  const std::uintmax_t size = fs::is_regular_file(file, ec) ? fs::file_size(file, ec) : 0;
  if (ec || !fs::is_regular_file(file, ec)) {
    error = "the file is missing or unreadable";
    return {};
  }
  if (size > budget.limit()) {
    error = "the file has " + format_bytes(static_cast<double>(size)) + ", more than the memory available";
    return {};
  }
  if (!read_file_prefix(file, static_cast<std::size_t>(size), bytes, error)) return {};
  return bytes;
}

}  // namespace atrium::assets::gltf
