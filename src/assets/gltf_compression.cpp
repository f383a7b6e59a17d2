#include "assets/gltf_compression.hpp"

#include <cstring>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>
#include <meshoptimizer.h>

namespace atrium::assets::gltf {
namespace {

std::string file_of(const Document& document) { return document.path.string(); }

template <typename T>
bool store_draco_values(const draco::PointAttribute& attribute, std::size_t points, int components, std::vector<std::uint8_t>& out) {
  T values[16];
  for (std::size_t i = 0; i < points; ++i) {
    const draco::AttributeValueIndex value = attribute.mapped_index(draco::PointIndex(static_cast<std::uint32_t>(i)));
    if (value.value() >= attribute.size()) return false;
    if (!attribute.ConvertValue<T>(value, static_cast<std::int8_t>(components), values)) return false;
    std::memcpy(out.data() + i * sizeof(T) * static_cast<std::size_t>(components), values, sizeof(T) * static_cast<std::size_t>(components));
  }
  return true;
}

}  // namespace

std::vector<std::uint8_t> decode_meshopt(const Document& document, std::size_t view_index, const MemoryBudget& budget) {
  const BufferView& view = document.buffer_views[view_index];
  const MeshoptSource& m = *view.meshopt;
  const std::string where = (element("bufferViews", view_index) / "extensions" / "EXT_meshopt_compression").str();
  const std::size_t size = m.count * m.byte_stride;  // == view.byte_length, checked when read
  if (size / kMeshoptMaxExpansion > m.byte_length + 4096) {
    throw ImportError(file_of(document) + ": " + where + " decodes to " + format_bytes(static_cast<double>(size)) + " from " +
                      format_bytes(static_cast<double>(m.byte_length)) + ", more than a meshopt stream can hold");
  }
  budget.require(size, where);
  std::vector<std::uint8_t> out(size);
  const std::uint8_t* source = document.buffers[m.buffer].data.data() + m.byte_offset;
  int status = -1;
  switch (m.mode) {
    case MeshoptSource::Mode::Attributes: status = meshopt_decodeVertexBuffer(out.data(), m.count, m.byte_stride, source, m.byte_length); break;
    case MeshoptSource::Mode::Triangles: status = meshopt_decodeIndexBuffer(out.data(), m.count, m.byte_stride, source, m.byte_length); break;
    case MeshoptSource::Mode::Indices: status = meshopt_decodeIndexSequence(out.data(), m.count, m.byte_stride, source, m.byte_length); break;
  }
  if (status != 0) throw ImportError(file_of(document) + ": " + where + " cannot be decoded (corrupt data, meshopt status " + std::to_string(status) + ")");
  switch (m.filter) {
    case MeshoptSource::Filter::None: break;
    case MeshoptSource::Filter::Octahedral: meshopt_decodeFilterOct(out.data(), m.count, m.byte_stride); break;
    case MeshoptSource::Filter::Quaternion: meshopt_decodeFilterQuat(out.data(), m.count, m.byte_stride); break;
    case MeshoptSource::Filter::Exponential: meshopt_decodeFilterExp(out.data(), m.count, m.byte_stride); break;
  }
  return out;
}

DecodedDraco decode_draco(const Document& document, const Primitive& primitive, std::span<const std::uint8_t> stream,
                          const std::string& where, const MemoryBudget& budget) {
  const std::string file = file_of(document);
  const std::string what = where + "/extensions/KHR_draco_mesh_compression";
  auto fail = [&](const std::string& problem) -> void { throw ImportError(file + ": " + what + " " + problem); };
  const DracoPrimitive& draco_primitive = *primitive.draco;

  // Decoding holds each attribute twice (Draco's copy and ours) plus Draco's
  // point-to-value map; the accessors' declared counts bound that up front.
  std::size_t declared = 0;
  for (const auto& [semantic, accessor] : primitive.attributes) {
    const Accessor& a = document.accessors[static_cast<std::size_t>(accessor)];
    if (draco_primitive.attributes.contains(semantic)) declared += a.count * (2 * a.element_size() + 4);
  }
  if (primitive.indices >= 0) declared += document.accessors[static_cast<std::size_t>(primitive.indices)].count * 8;
  budget.require(declared, what);

  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(stream.data()), stream.size());
  const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) fail("cannot be decoded: " + type.status().error_msg_string());
  if (type.value() != draco::TRIANGULAR_MESH) fail("holds a point cloud, not a triangle mesh");
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) fail("cannot be decoded: " + decoded.status().error_msg_string());
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  const std::size_t points = mesh->num_points();

  DecodedDraco out;
  auto differs = [&](const char* things, std::size_t decoded, std::size_t declared_count) {
    out.warnings.push_back(what + " decodes to " + std::to_string(decoded) + " " + things + ", its accessor declares " +
                           std::to_string(declared_count) + "; the decoded data is used");
  };
  if (primitive.indices >= 0) {
    const Accessor& a = document.accessors[static_cast<std::size_t>(primitive.indices)];
    const std::size_t count = static_cast<std::size_t>(mesh->num_faces()) * 3;
    if (a.count != count) differs("indices", count, a.count);
    DecodedAccessor indices{std::vector<std::uint8_t>(budget.bytes(count, sizeof(std::uint32_t), what)), count, kUnsignedInt};
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh->face(f)[k].value();
        std::memcpy(indices.bytes.data() + (static_cast<std::size_t>(f.value()) * 3 + static_cast<std::size_t>(k)) * sizeof index, &index,
                    sizeof index);
      }
    }
    out.accessors.emplace(primitive.indices, std::move(indices));
  }
  bool told_vertices = false;
  for (const auto& [semantic, id] : draco_primitive.attributes) {
    const auto accessor_it = primitive.attributes.find(semantic);
    if (accessor_it == primitive.attributes.end()) continue;  // the extension may carry attributes the primitive does not use
    const int accessor = accessor_it->second;
    const Accessor& a = document.accessors[static_cast<std::size_t>(accessor)];
    const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
    if (!attribute) fail("has no attribute " + std::to_string(id) + " for " + semantic);
    if (a.count != points && !told_vertices) {
      differs("vertices", points, a.count);
      told_vertices = true;
    }
    std::vector<std::uint8_t> bytes(budget.bytes(points, a.element_size(), what));
    bool ok = false;
    switch (a.component_type) {
      case kByte: ok = store_draco_values<std::int8_t>(*attribute, points, a.components, bytes); break;
      case kUnsignedByte: ok = store_draco_values<std::uint8_t>(*attribute, points, a.components, bytes); break;
      case kShort: ok = store_draco_values<std::int16_t>(*attribute, points, a.components, bytes); break;
      case kUnsignedShort: ok = store_draco_values<std::uint16_t>(*attribute, points, a.components, bytes); break;
      case kUnsignedInt: ok = store_draco_values<std::uint32_t>(*attribute, points, a.components, bytes); break;
      default: ok = store_draco_values<float>(*attribute, points, a.components, bytes); break;
    }
    if (!ok) fail("has values of " + semantic + " that do not convert to its accessor's component type");
    out.accessors.emplace(accessor, DecodedAccessor{std::move(bytes), points, a.component_type});
  }
  return out;
}

}  // namespace atrium::assets::gltf
