#include "assets/model_import.hpp"

#include <algorithm>
#include <array>

#include "assets/assimp_import.hpp"
#include "assets/gltf_import.hpp"

namespace atrium::assets {
namespace {

std::string extension_of(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The formats Atrium offers (assimp reads more; these are the ones tested or
// common among the scenes users bring).
constexpr std::array kAssimpExtensions{".obj", ".fbx", ".dae", ".3ds", ".ply", ".stl", ".x", ".lwo", ".ase", ".off"};

}  // namespace

std::optional<MaterialConvention> material_convention(std::string_view name) {
  if (name == "gltf") return MaterialConvention::Gltf;
  if (name == "bistro") return MaterialConvention::Bistro;
  if (name == "phong") return MaterialConvention::Phong;
  return std::nullopt;
}

bool is_model_file(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  return extension == ".gltf" || extension == ".glb" ||
         std::find(kAssimpExtensions.begin(), kAssimpExtensions.end(), extension) != kAssimpExtensions.end();
}

ModelImport import_model(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  const std::string extension = extension_of(path);
  if (extension == ".gltf" || extension == ".glb") return import_gltf(path, assets, options);
  return import_assimp(path, assets, options);
}

}  // namespace atrium::assets
