// The AssetManager owns every loaded asset on the CPU side: mesh assets and
// textures, handed out as handles that components hold. GPU copies live in
// GpuAssets (gpu_assets.hpp), so that import and scene building are testable
// without a GL context.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "assets/dds.hpp"
#include "assets/handles.hpp"
#include "assets/image.hpp"
#include "assets/mesh_asset.hpp"

namespace atrium::assets {

enum class ColorSpace : std::uint8_t { Linear, Srgb };

struct TextureData {
  std::string name;
  Image image;  // empty when the texture is block-compressed
  ColorSpace color_space = ColorSpace::Linear;
  std::optional<CompressedImage> compressed;  // a DDS's blocks, uploaded as they are

  [[nodiscard]] int width() const { return compressed ? compressed->width : image.width; }
  [[nodiscard]] int height() const { return compressed ? compressed->height : image.height; }
  // Bytes held on the CPU (and, roughly, on the GPU without the mip chain).
  [[nodiscard]] std::size_t bytes() const { return compressed ? compressed->bytes() : image.rgba.size(); }
};

class AssetManager {
 public:
  // `key` caches the asset (a canonical path for files); an empty key never caches.
  MeshAssetHandle add_mesh_asset(MeshAsset asset, const std::string& key = {});
  TextureHandle add_texture(TextureData texture, const std::string& key = {});

  [[nodiscard]] TextureHandle find_texture(const std::string& key) const;

  [[nodiscard]] const MeshAsset& mesh_asset(MeshAssetHandle handle) const;
  [[nodiscard]] const TextureData& texture(TextureHandle handle) const;
  [[nodiscard]] std::size_t mesh_asset_count() const { return mesh_assets_.size(); }
  [[nodiscard]] std::size_t texture_count() const { return textures_.size(); }

 private:
  std::vector<MeshAsset> mesh_assets_;
  std::vector<TextureData> textures_;
  std::unordered_map<std::string, MeshAssetHandle> mesh_keys_;
  std::unordered_map<std::string, TextureHandle> texture_keys_;
};

}  // namespace atrium::assets
