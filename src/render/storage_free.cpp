#include "render/storage_free.hpp"

#include <algorithm>

namespace atrium::render {
namespace {

// texelFetch reads them, but an integer texture (or a float one on GLES without
// OES_texture_float_linear) with a filtering sampler state is incomplete.
void set_nearest(const gfx::Texture& texture) {
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void append_texels(const InstanceData& instance, std::vector<glm::vec4>& texels) {
  for (int c = 0; c < 4; ++c) texels.push_back(instance.model[c]);
  for (int c = 0; c < 4; ++c) texels.push_back(instance.normal_matrix[c]);
  texels.emplace_back(glm::vec4(instance.material));
}

}  // namespace

void storage_defines(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
  if (inputs.settings.technique_options.compute_free) defines.push_back({"NO_STORAGE_BUFFERS"});
}

std::vector<glm::vec4> instance_texels(std::span<const InstanceData> instances) {
  std::vector<glm::vec4> texels;
  texels.reserve(instances.size() * kInstanceTexels);
  for (const InstanceData& instance : instances) append_texels(instance, texels);
  return texels;
}

std::vector<glm::vec4> instance_texels(std::span<const InstanceData> instances, std::span<const InstanceSlot> slots) {
  std::vector<glm::vec4> texels;
  texels.reserve(slots.size() * kInstanceTexels);
  for (const InstanceSlot& slot : slots) append_texels(instances[slot.record], texels);
  return texels;
}

std::vector<glm::vec4> material_texels(std::span<const MaterialData> materials) {
  std::vector<glm::vec4> texels;
  texels.reserve(materials.size() * kMaterialTexels);
  for (const MaterialData& m : materials) {
    texels.push_back(m.base_color_factor);
    texels.push_back(m.emissive);
    texels.emplace_back(m.metallic_factor, m.roughness_factor, m.occlusion_strength, m.alpha_cutoff);
    texels.emplace_back(static_cast<float>(m.flags), static_cast<float>(m.uv_sets), 0.0f, 0.0f);
    for (const glm::vec4& row : m.uv_transform) texels.push_back(row);
  }
  return texels;
}

void RecordTexture::upload(const void* data, std::size_t records) {
  const auto width = static_cast<GLsizei>(per_row_ * texels_);
  const int rows = static_cast<int>(std::max<std::size_t>((records + per_row_ - 1) / per_row_, 1));
  if (!texture_ || rows > rows_) {
    rows_ = std::max(rows, 2 * rows_);
    texture_ = gfx::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), 1, format_.internal_format, width, rows_);
    set_nearest(texture_);
  }
  // Whole rows, then the last row's records.
  const auto* bytes = static_cast<const unsigned char*>(data);
  const std::size_t full_rows = records / per_row_, rest = records % per_row_;
  if (full_rows > 0) {
    glTextureSubImage2D(texture_.id(), 0, 0, 0, width, static_cast<GLsizei>(full_rows), format_.pixel_format, format_.type, bytes);
  }
  if (rest > 0) {
    glTextureSubImage2D(texture_.id(), 0, 0, static_cast<GLint>(full_rows), static_cast<GLsizei>(rest * texels_), 1, format_.pixel_format,
                        format_.type, bytes + full_rows * per_row_ * texels_ * format_.bytes);
  }
}

void RecordTexture::bind(GLuint unit) const { glBindTextureUnit(unit, texture_.id()); }

void ListTextures::upload(const lighting::CpuLightLists& lists) {
  ranges_.upload(lists.ranges.data(), lists.ranges.size());
  indices_.upload(lists.indices.data(), lists.indices.size());
  entries_ = static_cast<std::uint32_t>(lists.indices.size());
}

void ListTextures::bind() const {
  ranges_.bind(kLightRangeTextureUnit);
  indices_.bind(kLightIndexTextureUnit);
}

void StorageFreeRecords::upload(std::span<const GpuLight> lights, const DrawList& draws) {
  lights_.upload(std::span<const glm::vec4>(reinterpret_cast<const glm::vec4*>(lights.data()), lights.size() * kLightTexels));
  // No base instances here, so no instance-slot buffer: a draw's instances
  // are the constant attribute plus gl_InstanceID (common/mesh.vert), and
  // the records are laid out slot by slot (the list's meshlet runs of one
  // primitive instance each hold a copy).
  instances_.upload(instance_texels(draws.instances, draws.slots));
  materials_.upload(material_texels(draws.materials));
}

void StorageFreeRecords::bind() const {
  lights_.bind(kLightTextureUnit);
  instances_.bind(kInstanceTextureUnit);
  materials_.bind(kMaterialTextureUnit);
}

}  // namespace atrium::render
