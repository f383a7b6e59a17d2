// GPU copies of the AssetManager's contents: one vertex and one index pool for
// every mesh asset, drawn through one vertex array (primitives are ranges in
// them; vertex buffers that primitives share are uploaded once), so that a
// compute shader reaches any triangle (the visibility buffer's resolve), one
// mipmapped texture per image,
// neutral 1x1 defaults for the texture slots a material leaves empty, sampler
// objects, and the shader programs (cached by files and defines).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "assets/asset_manager.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"

namespace atrium::render {

// The vertex attribute that says which instance a vertex belongs to: two
// unsigned integers a draw instance (render::InstanceSlot), fed from binding 1
// of the vertex array with a divisor of 1 (use_slots).
inline constexpr GLuint kInstanceSlotLocation = 6;
inline constexpr GLsizei kInstanceSlotBytes = 8;

struct GpuPrimitive {
  std::uint32_t first_index = 0;  // in the index pool
  std::uint32_t index_count = 0;
  std::int32_t base_vertex = 0;   // in the vertex pool
};

struct GpuMeshAsset {
  std::vector<std::vector<GpuPrimitive>> meshes;  // [mesh][primitive]
};

class GpuAssets {
 public:
  // `max_texture_size`: the widest and tallest texture to upload (0: as large as
  // the context allows, GL_MAX_TEXTURE_SIZE); larger images are downscaled.
  explicit GpuAssets(int max_texture_size = 0) : max_texture_size_(max_texture_size) {}

  // Uploads everything the AssetManager holds that is not on the GPU yet and
  // returns a warning for each texture it had to downscale. Needs a current GL
  // 4.5 context.
  std::vector<std::string> upload(const assets::AssetManager& assets);

  [[nodiscard]] const GpuMeshAsset& mesh_asset(assets::MeshAssetHandle handle) const { return mesh_assets_.at(handle.index); }
  // The one vertex array every mesh is drawn through (the pools, and the
  // instance slots at kInstanceSlotLocation).
  [[nodiscard]] GLuint vertex_array() const { return vertex_array_.id(); }
  // The pools as storage buffers: assets::Vertex records (64 bytes) and 32-bit indices.
  [[nodiscard]] GLuint vertex_pool() const { return vertices_.id(); }
  [[nodiscard]] GLuint index_pool() const { return indices_.id(); }
  [[nodiscard]] std::size_t geometry_bytes() const { return geometry_bytes_; }
  // Feeds attribute kInstanceSlotLocation from `buffer`, a list's slots: an
  // instanced draw with base instance B gives its instances slots B, B+1, ...
  void use_slots(GLuint buffer);
  // ... or from identity slots ({i, 0} at i), at least `count`, for a list
  // whose instance i draws record i (the shadow casters).
  void use_identity_slots(std::size_t count);
  // The texture's GL name, or the white default for an empty handle.
  [[nodiscard]] GLuint texture(assets::TextureHandle handle) const;
  // Whether it holds two channels (BC5): a normal map's z is then rebuilt from x and y.
  [[nodiscard]] bool two_channel(assets::TextureHandle handle) const;
  // The sampler object for `desc` (made by upload for every material slot).
  [[nodiscard]] GLuint sampler(const assets::SamplerDesc& desc) const;
  [[nodiscard]] std::size_t texture_bytes() const { return texture_bytes_; }
  // The resident bindless handle (ARB_bindless_texture) of `texture` sampled
  // through `sampler` (0: the texture's own state), made at the first ask.
  // Both are GpuAssets' own and live as long as it: so does the handle, and
  // neither's state may change after (the extension freezes it).
  [[nodiscard]] GLuint64 texture_handle(GLuint texture, GLuint sampler);
  // Shader programs, cached by files and defines.
  [[nodiscard]] gfx::ShaderLibrary& shaders() { return shaders_; }

 private:
  void make_sampler(const assets::SamplerDesc& desc);
  // Uploads every mesh asset into new pools (assets arrive at load time, rarely
  // and all at once: one rebuild beats a growth policy) and points the vertex array at them.
  void build_pools(const assets::AssetManager& assets);

  int max_texture_size_;
  std::vector<GpuMeshAsset> mesh_assets_;
  gfx::Buffer vertices_, indices_;
  gfx::VertexArray vertex_array_;
  std::size_t geometry_bytes_ = 0;
  std::vector<gfx::Texture> textures_;
  std::vector<bool> two_channel_;
  gfx::Texture white_;
  gfx::Buffer identity_slots_;
  std::size_t identity_capacity_ = 0;
  std::map<assets::SamplerDesc, gfx::Sampler> samplers_;
  std::map<std::pair<GLuint, GLuint>, GLuint64> handles_;
  gfx::ShaderLibrary shaders_;
  std::size_t texture_bytes_ = 0;
};

}  // namespace atrium::render
