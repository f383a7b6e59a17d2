#include "render/gpu_assets.hpp"

#include <algorithm>
#include <cstddef>

#include "base/mip_levels.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"

namespace atrium::render {
namespace {

constexpr float kMaxAnisotropy = 8.0f;

GLenum image_format(assets::ColorSpace color_space) { return color_space == assets::ColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8; }

gfx::Texture upload_image(const assets::Image& image, assets::ColorSpace color_space, std::size_t& bytes) {
  const int levels = mip_levels(image.width, image.height);
  gfx::Texture texture = gfx::create_texture(GL_TEXTURE_2D);
  const GLenum format = image_format(color_space);
  glTextureStorage2D(texture.id(), levels, format, image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  if (levels > 1) glGenerateTextureMipmap(texture.id());
  bytes += static_cast<std::size_t>(image.width) * image.height * 4 * 4 / 3;  // with the mip chain
  return texture;
}

// The GL format of a block format in a colour space (BC4 and BC5 hold data, never colour).
GLenum compressed_format(assets::BlockFormat format, assets::ColorSpace space) {
  const bool srgb = space == assets::ColorSpace::Srgb;
  switch (format) {
    case assets::BlockFormat::BC1: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT : GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
    case assets::BlockFormat::BC2: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT : GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
    case assets::BlockFormat::BC3: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT : GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    case assets::BlockFormat::BC4: return GL_COMPRESSED_RED_RGTC1;
    case assets::BlockFormat::BC5: return GL_COMPRESSED_RG_RGTC2;
    case assets::BlockFormat::BC7: return srgb ? GL_COMPRESSED_SRGB_ALPHA_BPTC_UNORM : GL_COMPRESSED_RGBA_BPTC_UNORM;
  }
  return GL_NONE;
}

// RGTC (BC4, BC5) and BPTC (BC7) are core since GL 3.0 and 4.2; S3TC (BC1-BC3)
// is an extension, with sRGB variants of its own.
bool compressed_supported(assets::BlockFormat format) {
  if (format == assets::BlockFormat::BC4 || format == assets::BlockFormat::BC5 || format == assets::BlockFormat::BC7) return true;
  return epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc") &&
         (epoxy_has_gl_extension("GL_EXT_texture_sRGB") || epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc_srgb"));
}

// Uploads a DDS's levels from `first` on, as they are.
gfx::Texture upload_compressed(const assets::CompressedImage& image, std::size_t first, assets::ColorSpace space, std::size_t& bytes) {
  const int levels = static_cast<int>(image.levels.size() - first);
  const GLenum format = compressed_format(image.format, space);
  gfx::Texture texture = gfx::create_texture(GL_TEXTURE_2D);
  const int width = std::max(1, image.width >> first), height = std::max(1, image.height >> first);
  glTextureStorage2D(texture.id(), levels, format, width, height);
  for (int level = 0; level < levels; ++level) {
    const auto& data = image.levels[first + static_cast<std::size_t>(level)];
    glCompressedTextureSubImage2D(texture.id(), level, 0, 0, std::max(1, width >> level), std::max(1, height >> level), format,
                                  static_cast<GLsizei>(data.size()), data.data());
    bytes += data.size();
  }
  // One channel of data reads as grey, as a greyscale PNG does.
  if (image.format == assets::BlockFormat::BC4) {
    const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTextureParameteriv(texture.id(), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
  }
  return texture;
}

}  // namespace

std::vector<std::string> GpuAssets::upload(const assets::AssetManager& assets) {
  std::vector<std::string> warnings;
  if (!white_) {
    const assets::Image white{1, 1, {255, 255, 255, 255}};
    std::size_t ignored = 0;
    white_ = upload_image(white, assets::ColorSpace::Linear, ignored);
    make_sampler(assets::SamplerDesc{});
  }
  const int context_limit = gfx::max_texture_size();
  const int limit = max_texture_size_ > 0 ? std::min(max_texture_size_, context_limit) : context_limit;
  const auto wxh = [](glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); };
  // How every warning names a texture.
  const auto named = [](std::size_t t, const assets::TextureData& data) { return "texture " + std::to_string(t) + " '" + data.name + "'"; };
  // `done`: how the smaller texture is made ("downscaled to ", "uploaded from its mip level of ").
  auto too_large = [&](std::size_t t, const assets::TextureData& data, glm::ivec2 to, const char* done) {
    return named(t, data) + " is " + wxh({data.width(), data.height()}) + ", more than " +
           (limit < context_limit ? "--max-texture-size allows (" + std::to_string(limit) + ")"
                                  : "this context allows (" + std::to_string(limit) + ", GL_MAX_TEXTURE_SIZE)") +
           "; it is " + done + wxh(to);
  };
  auto not_held = [&](std::size_t t, const assets::TextureData& data, glm::ivec2 from, glm::ivec2 to, const char* done) {
    return named(t, data) + " at " + wxh(from) +
           " is more than this context can hold (its proxy texture refused it); it is " + done + wxh(to);
  };
  // Within GL_MAX_TEXTURE_SIZE a driver may still lack the memory (zink over
  // lavapipe refuses 16384x16384 RGBA8 with its mips): halved until the proxy
  // takes it, rather than a texture without storage that samples black.
  auto upload_held = [&](std::size_t t, const assets::TextureData& data, const assets::Image& image) {
    const glm::ivec2 size(image.width, image.height);
    glm::ivec2 held = size;
    while (std::max(held.x, held.y) > 1 && !gfx::texture_fits(image_format(data.color_space), mip_levels(held.x, held.y), held)) held = glm::max(held / 2, 1);
    if (held == size) return upload_image(image, data.color_space, texture_bytes_);
    const assets::Image smaller = assets::downscale_to_fit(image, std::max(held.x, held.y), data.color_space == assets::ColorSpace::Srgb);
    warnings.push_back(not_held(t, data, size, {smaller.width, smaller.height}, "downscaled to "));
    return upload_image(smaller, data.color_space, texture_bytes_);
  };
  // A DDS's blocks: uploaded as they are from the first mip level within the
  // limit (levels over it are neither uploaded nor decoded), or decoded where
  // the driver cannot sample them or no level is within the limit (a file
  // without a mip chain), to be downscaled.
  auto upload_blocks = [&](std::size_t t, const assets::TextureData& data) {
    const assets::CompressedImage& image = *data.compressed;
    const auto size_from = [&](std::size_t first) {
      return glm::ivec2(std::max(1, image.width >> first), std::max(1, image.height >> first));
    };
    std::size_t first = 0;
    while (first + 1 < image.levels.size() && std::max(size_from(first).x, size_from(first).y) > limit) ++first;
    const bool within = std::max(size_from(first).x, size_from(first).y) <= limit;
    const bool sampled = compressed_supported(image.format);
    std::string error;
    std::optional<assets::Image> decoded;
    if (!sampled || !within) {
      decoded = first == 0 ? assets::decode_blocks(image, error)
                           : assets::decode_blocks({image.format, size_from(first).x, size_from(first).y, {image.levels[first]}}, error);
    }
    if (!decoded && sampled) {
      if (first > 0) warnings.push_back(too_large(t, data, size_from(first), "uploaded from its mip level of "));
      if (!within) {
        warnings.push_back(named(t, data) + " is " + wxh(size_from(first)) +
                           " at its smallest level, more than the limit (" + std::to_string(limit) + "), and " +
                           assets::block_format_name(image.format) + " blocks cannot be decoded here to downscale it; it is uploaded as it is");
      }
      const std::size_t within_limit = first;
      const GLenum format = compressed_format(image.format, data.color_space);
      while (first + 1 < image.levels.size() && !gfx::texture_fits(format, static_cast<int>(image.levels.size() - first), size_from(first))) {
        ++first;
      }
      if (first > within_limit) warnings.push_back(not_held(t, data, size_from(within_limit), size_from(first), "uploaded from its mip level of "));
      return upload_compressed(image, first, data.color_space, texture_bytes_);
    }
    if (!decoded) {
      warnings.push_back(named(t, data) + " is " + error + "; a neutral default is used");
      return upload_image(assets::Image{1, 1, {255, 255, 255, 255}}, assets::ColorSpace::Linear, texture_bytes_);
    }
    if (!sampled) {
      warnings.push_back(named(t, data) + " is " + assets::block_format_name(image.format) +
                         ", which this driver cannot sample; it is decoded and uploaded uncompressed");
    }
    if (within) {
      if (first > 0) warnings.push_back(too_large(t, data, size_from(first), "decoded from its mip level of "));
      return upload_held(t, data, *decoded);
    }
    const assets::Image smaller = assets::downscale_to_fit(*decoded, limit, data.color_space == assets::ColorSpace::Srgb);
    warnings.push_back(too_large(t, data, {smaller.width, smaller.height}, "decoded and downscaled to "));
    return upload_held(t, data, smaller);
  };
  for (std::size_t t = textures_.size(); t < assets.texture_count(); ++t) {
    const assets::TextureData& data = assets.texture(assets::TextureHandle{static_cast<std::uint32_t>(t)});
    two_channel_.push_back(data.compressed && data.compressed->format == assets::BlockFormat::BC5);
    if (data.compressed) {
      textures_.push_back(upload_blocks(t, data));
      continue;
    }
    if (data.image.width <= limit && data.image.height <= limit) {
      textures_.push_back(upload_held(t, data, data.image));
      continue;
    }
    const assets::Image smaller = assets::downscale_to_fit(data.image, limit, data.color_space == assets::ColorSpace::Srgb);
    warnings.push_back(too_large(t, data, {smaller.width, smaller.height}, "downscaled to "));
    textures_.push_back(upload_held(t, data, smaller));
  }
  if (mesh_assets_.size() < assets.mesh_asset_count()) {
    for (std::size_t a = mesh_assets_.size(); a < assets.mesh_asset_count(); ++a) {
      for (const assets::Material& m : assets.mesh_asset(assets::MeshAssetHandle{static_cast<std::uint32_t>(a)}).materials) {
        for (const assets::TextureSlot* slot : m.texture_slots()) make_sampler(slot->sampler);
      }
    }
    build_pools(assets);
  }
  return warnings;
}

void GpuAssets::build_pools(const assets::AssetManager& assets) {
  // Every vertex buffer once, primitives as index ranges with the base
  // vertex of the buffer they index: shared vertices stay shared.
  std::size_t vertex_total = 0, index_total = 0;
  for (std::size_t a = 0; a < assets.mesh_asset_count(); ++a) {
    const assets::MeshAsset& asset = assets.mesh_asset(assets::MeshAssetHandle{static_cast<std::uint32_t>(a)});
    for (const auto& vertices : asset.vertex_buffers) vertex_total += vertices.size();
    for (const assets::Mesh& mesh : asset.meshes) {
      for (const assets::Primitive& p : mesh.primitives) index_total += p.indices.size();
    }
  }
  vertices_ = gfx::create_buffer();
  indices_ = gfx::create_index_buffer();
  const std::size_t vertex_bytes = std::max<std::size_t>(1, vertex_total) * sizeof(assets::Vertex);
  const std::size_t index_bytes = std::max<std::size_t>(1, index_total) * sizeof(std::uint32_t);
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(vertex_bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(index_bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  geometry_bytes_ = vertex_bytes + index_bytes;
  // Without glDrawElements*BaseVertex (ES 3.0, WebGL2) the indices are
  // stored already offset by their buffer's first vertex, and every range
  // draws from vertex 0.
  const bool offset_indices = !gfx::gl_features().base_vertex;
  std::vector<std::uint32_t> offset;
  std::size_t first_vertex = 0, first_index = 0;
  mesh_assets_.clear();
  for (std::size_t a = 0; a < assets.mesh_asset_count(); ++a) {
    const assets::MeshAsset& asset = assets.mesh_asset(assets::MeshAssetHandle{static_cast<std::uint32_t>(a)});
    std::vector<std::int32_t> base_vertex(asset.vertex_buffers.size());
    for (std::size_t b = 0; b < asset.vertex_buffers.size(); ++b) {
      const auto& vertices = asset.vertex_buffers[b];
      base_vertex[b] = static_cast<std::int32_t>(first_vertex);
      if (!vertices.empty()) {
        glNamedBufferSubData(vertices_.id(), static_cast<GLintptr>(first_vertex * sizeof(assets::Vertex)),
                             static_cast<GLsizeiptr>(vertices.size() * sizeof(assets::Vertex)), vertices.data());
      }
      first_vertex += vertices.size();
    }
    GpuMeshAsset& gpu = mesh_assets_.emplace_back();
    for (const assets::Mesh& mesh : asset.meshes) {
      auto& ranges = gpu.meshes.emplace_back();
      for (const assets::Primitive& p : mesh.primitives) {
        const std::int32_t base = base_vertex.at(p.vertex_buffer);
        ranges.push_back({static_cast<std::uint32_t>(first_index), static_cast<std::uint32_t>(p.indices.size()), offset_indices ? 0 : base});
        const std::uint32_t* indices = p.indices.data();
        if (offset_indices) {
          offset.resize(p.indices.size());
          std::transform(p.indices.begin(), p.indices.end(), offset.begin(),
                         [&](std::uint32_t i) { return i + static_cast<std::uint32_t>(base); });
          indices = offset.data();
        }
        if (!p.indices.empty()) {
          glNamedBufferSubData(indices_.id(), static_cast<GLintptr>(first_index * sizeof(std::uint32_t)),
                               static_cast<GLsizeiptr>(p.indices.size() * sizeof(std::uint32_t)), indices);
        }
        first_index += p.indices.size();
      }
    }
  }

  vertex_array_ = gfx::create_vertex_array();
  const GLuint vao = vertex_array_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(assets::Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  struct Attribute {
    GLuint location;
    GLint components;
    GLenum type;
    GLboolean normalized;
    std::size_t offset;
  };
  const Attribute attributes[] = {{0, 3, GL_FLOAT, GL_FALSE, offsetof(assets::Vertex, position)},
                                  {1, 3, GL_FLOAT, GL_FALSE, offsetof(assets::Vertex, normal)},
                                  {2, 4, GL_FLOAT, GL_FALSE, offsetof(assets::Vertex, tangent)},
                                  {3, 2, GL_FLOAT, GL_FALSE, offsetof(assets::Vertex, uv0)},
                                  {4, 2, GL_FLOAT, GL_FALSE, offsetof(assets::Vertex, uv1)},
                                  {5, 4, GL_UNSIGNED_SHORT, GL_TRUE, offsetof(assets::Vertex, color)}};
  for (const auto& attribute : attributes) {
    glEnableVertexArrayAttrib(vao, attribute.location);
    glVertexArrayAttribFormat(vao, attribute.location, attribute.components, attribute.type, attribute.normalized,
                              static_cast<GLuint>(attribute.offset));
    glVertexArrayAttribBinding(vao, attribute.location, 0);
  }
  // Location 6: which instance slot a vertex belongs to (binding 1, one slot
  // per instance). Instanced draws offset it by their base instance.
  glEnableVertexArrayAttrib(vao, kInstanceSlotLocation);
  glVertexArrayAttribIFormat(vao, kInstanceSlotLocation, 2, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vao, kInstanceSlotLocation, 1);
  glVertexArrayBindingDivisor(vao, 1, 1);
  // Its buffer is bound by whichever list draws next (use_slots).
}

void GpuAssets::use_slots(GLuint buffer) {
  if (!vertex_array_) return;
  glVertexArrayVertexBuffer(vertex_array_.id(), 1, buffer, 0, kInstanceSlotBytes);
}

void GpuAssets::use_identity_slots(std::size_t count) {
  if (count > identity_capacity_ || !identity_slots_) {
    identity_capacity_ = std::max<std::size_t>({count, 2 * identity_capacity_, 1024});
    std::vector<glm::uvec2> identity(identity_capacity_);
    for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = {static_cast<std::uint32_t>(i), 0u};
    identity_slots_ = gfx::create_buffer();
    glNamedBufferStorage(identity_slots_.id(), static_cast<GLsizeiptr>(identity.size() * sizeof(glm::uvec2)), identity.data(), 0);
  }
  use_slots(identity_slots_.id());
}

GLuint GpuAssets::sampler(const assets::SamplerDesc& desc) const {
  auto it = samplers_.find(desc);
  return it != samplers_.end() ? it->second.id() : samplers_.at(assets::SamplerDesc{}).id();
}

void GpuAssets::make_sampler(const assets::SamplerDesc& desc) {
  if (samplers_.contains(desc)) return;
  gfx::Sampler sampler = gfx::create_sampler();
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, desc.mag_filter);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, desc.min_filter);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, desc.wrap_s);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, desc.wrap_t);
  const bool mipmapped = desc.min_filter != assets::SamplerDesc::kNearest && desc.min_filter != assets::SamplerDesc::kLinear;
  // llvmpipe filters anisotropically with an elliptical weighted average that
  // loops over every texel of a pixel's footprint. A leaf seen edge-on right at
  // the camera has a footprint of thousands of texels (its derivatives
  // extrapolate far beyond the triangle), and one 160x90 frame of Sponza spent
  // 80 s in those loops. GPUs bound the cost in hardware; software renderers
  // sample trilinearly.
  if (mipmapped && !gfx::is_software_renderer() &&
      (epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
       epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic"))) {
    glSamplerParameterf(sampler.id(), GL_TEXTURE_MAX_ANISOTROPY, kMaxAnisotropy);
  }
  samplers_.emplace(desc, std::move(sampler));
}

bool GpuAssets::two_channel(assets::TextureHandle handle) const {
  return handle.valid() && handle.index < two_channel_.size() && two_channel_[handle.index];
}

GLuint64 GpuAssets::texture_handle(GLuint texture, GLuint sampler) {
  const auto [it, made] = handles_.try_emplace({texture, sampler}, 0);
  if (made) {
    it->second = sampler != 0 ? glGetTextureSamplerHandleARB(texture, sampler) : glGetTextureHandleARB(texture);
    glMakeTextureHandleResidentARB(it->second);
  }
  return it->second;
}

GLuint GpuAssets::texture(assets::TextureHandle handle) const {
  return handle.valid() && handle.index < textures_.size() ? textures_[handle.index].id() : white_.id();
}

}  // namespace atrium::render
