#include "assets/asset_manager.hpp"

#include <stdexcept>

#include "assets/meshlets.hpp"

namespace atrium::assets {

namespace {
// Appends `value` unless `key` is already cached; an empty key never caches.
template <typename Handle, typename T>
Handle add_cached(std::vector<T>& values, std::unordered_map<std::string, Handle>& keys, T value, const std::string& key) {
  if (!key.empty()) {
    if (auto it = keys.find(key); it != keys.end()) return it->second;
  }
  const Handle handle{static_cast<std::uint32_t>(values.size())};
  values.push_back(std::move(value));
  if (!key.empty()) keys[key] = handle;
  return handle;
}
}  // namespace

MeshAssetHandle AssetManager::add_mesh_asset(MeshAsset asset, const std::string& key) {
  const std::size_t before = mesh_assets_.size();
  const MeshAssetHandle handle = add_cached(mesh_assets_, mesh_keys_, std::move(asset), key);
  if (mesh_assets_.size() > before) build_meshlets(mesh_assets_.back());  // new, not a cached key
  return handle;
}

TextureHandle AssetManager::add_texture(TextureData texture, const std::string& key) {
  return add_cached(textures_, texture_keys_, std::move(texture), key);
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
