#include "render/storage_free.hpp"

#include <algorithm>
#include <cstring>

namespace atrium::render {
namespace {

// texelFetch reads them, but an integer texture (or a float one on GLES without
// OES_texture_float_linear) with a filtering sampler state is incomplete.
void set_nearest(const gfx::Texture& texture) {
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

}  // namespace

void storage_defines(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
  if (inputs.settings.technique_options.compute_free) defines.push_back({"NO_STORAGE_BUFFERS"});
}

std::vector<glm::vec4> instance_texels(std::span<const lighting::InstanceData> instances) {
  std::vector<glm::vec4> texels;
  texels.reserve(instances.size() * kInstanceTexels);
  for (const lighting::InstanceData& instance : instances) {
    for (int c = 0; c < 4; ++c) texels.push_back(instance.model[c]);
    for (int c = 0; c < 4; ++c) texels.push_back(instance.normal_matrix[c]);
    texels.emplace_back(glm::vec4(instance.material));
  }
  return texels;
}

std::vector<glm::vec4> material_texels(std::span<const lighting::MaterialData> materials) {
  std::vector<glm::vec4> texels;
  texels.reserve(materials.size() * kMaterialTexels);
  for (const lighting::MaterialData& m : materials) {
    texels.push_back(m.base_color_factor);
    texels.push_back(m.emissive);
    texels.emplace_back(m.metallic_factor, m.roughness_factor, m.occlusion_strength, m.alpha_cutoff);
    texels.emplace_back(static_cast<float>(m.flags), static_cast<float>(m.uv_sets), 0.0f, 0.0f);
    for (const glm::vec4& row : m.uv_transform) texels.push_back(row);
  }
  return texels;
}

void RecordTexture::upload(std::span<const glm::vec4> texels) {
  const std::size_t records = texels.size() / texels_;
  const auto width = static_cast<int>(per_row_ * texels_);
  const int rows = static_cast<int>(std::max<std::size_t>((records + per_row_ - 1) / per_row_, 1));
  if (!texture_ || rows > size_.y) {
    size_ = glm::ivec2(width, std::max(rows, 2 * size_.y));
    texture_ = gfx::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, size_.x, size_.y);
    set_nearest(texture_);
  }
  if (records == 0) return;
  // Whole rows, then the last row's records.
  const std::size_t full_rows = records / per_row_;
  if (full_rows > 0) {
    glTextureSubImage2D(texture_.id(), 0, 0, 0, width, static_cast<GLsizei>(full_rows), GL_RGBA, GL_FLOAT, texels.data());
  }
  const std::size_t rest = records % per_row_;
  if (rest > 0) {
    glTextureSubImage2D(texture_.id(), 0, 0, static_cast<GLint>(full_rows), static_cast<GLsizei>(rest * texels_), 1, GL_RGBA, GL_FLOAT,
                        texels.data() + full_rows * per_row_ * texels_);
  }
}

void RecordTexture::bind(GLuint unit) const { glBindTextureUnit(unit, texture_.id()); }

namespace {

// Grows `texture` to hold `count` texels of `format` in rows of
// kListTextureWidth, and uploads `texels` (whole rows, then the rest).
void upload_rows(gfx::Texture& texture, int& rows, GLenum format, GLenum pixel_format, const void* texels, std::size_t count,
                 std::size_t texel_bytes) {
  const int needed = static_cast<int>(std::max<std::size_t>((count + kListTextureWidth - 1) / kListTextureWidth, 1));
  if (!texture || needed > rows) {
    rows = std::max(needed, 2 * rows);
    texture = gfx::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, format, static_cast<GLsizei>(kListTextureWidth), rows);
    set_nearest(texture);
  }
  const std::size_t full_rows = count / kListTextureWidth, rest = count % kListTextureWidth;
  const auto* bytes = static_cast<const unsigned char*>(texels);
  if (full_rows > 0) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, static_cast<GLsizei>(kListTextureWidth), static_cast<GLsizei>(full_rows), pixel_format,
                        GL_UNSIGNED_INT, bytes);
  }
  if (rest > 0) {
    glTextureSubImage2D(texture.id(), 0, 0, static_cast<GLint>(full_rows), static_cast<GLsizei>(rest), 1, pixel_format, GL_UNSIGNED_INT,
                        bytes + full_rows * kListTextureWidth * texel_bytes);
  }
}

}  // namespace

void ListTextures::upload(std::span<const glm::uvec2> ranges, std::span<const std::uint32_t> indices) {
  upload_rows(ranges_, range_rows_, GL_RG32UI, GL_RG_INTEGER, ranges.data(), ranges.size(), sizeof(glm::uvec2));
  upload_rows(indices_, index_rows_, GL_R32UI, GL_RED_INTEGER, indices.data(), indices.size(), sizeof(std::uint32_t));
}

void ListTextures::bind() const {
  glBindTextureUnit(kLightRangeTextureUnit, ranges_.id());
  glBindTextureUnit(kLightIndexTextureUnit, indices_.id());
}

void StorageFreeRecords::upload(std::span<const GpuLight> lights, const lighting::DrawList& draws) {
  lights_.upload(std::span<const glm::vec4>(reinterpret_cast<const glm::vec4*>(lights.data()), lights.size() * kLightTexels));
  instances_.upload(instance_texels(draws.instances));
  materials_.upload(material_texels(draws.materials));
}

void StorageFreeRecords::bind() const {
  lights_.bind(kLightTextureUnit);
  instances_.bind(kInstanceTextureUnit);
  materials_.bind(kMaterialTextureUnit);
}

}  // namespace atrium::render
