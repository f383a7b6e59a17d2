#include "assets/asset_manager.hpp"

#include <stdexcept>

namespace atrium::assets {

MeshAssetHandle AssetManager::add_mesh_asset(MeshAsset asset, const std::string& key) {
  if (!key.empty()) {
    if (auto found = find_mesh_asset(key); found.valid()) return found;
  }
  const MeshAssetHandle handle{static_cast<std::uint32_t>(mesh_assets_.size())};
  mesh_assets_.push_back(std::move(asset));
  if (!key.empty()) mesh_keys_[key] = handle;
  return handle;
}

TextureHandle AssetManager::add_texture(TextureData texture, const std::string& key) {
  if (!key.empty()) {
    if (auto found = find_texture(key); found.valid()) return found;
  }
  const TextureHandle handle{static_cast<std::uint32_t>(textures_.size())};
  textures_.push_back(std::move(texture));
  if (!key.empty()) texture_keys_[key] = handle;
  return handle;
}

MeshAssetHandle AssetManager::find_mesh_asset(const std::string& key) const {
  auto it = mesh_keys_.find(key);
  return it == mesh_keys_.end() ? MeshAssetHandle{} : it->second;
}

TextureHandle AssetManager::find_texture(const std::string& key) const {
  auto it = texture_keys_.find(key);
  return it == texture_keys_.end() ? TextureHandle{} : it->second;
}

const MeshAsset& AssetManager::mesh_asset(MeshAssetHandle handle) const {
  if (handle.index >= mesh_assets_.size()) throw std::out_of_range("AssetManager: invalid mesh asset handle");
  return mesh_assets_[handle.index];
}

const TextureData& AssetManager::texture(TextureHandle handle) const {
  if (handle.index >= textures_.size()) throw std::out_of_range("AssetManager: invalid texture handle");
  return textures_[handle.index];
}

}  // namespace atrium::assets
