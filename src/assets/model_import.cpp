#include "assets/model_import.hpp"

#include <algorithm>
#include <array>

#include "assets/assimp_import.hpp"
#include "assets/file_lookup.hpp"
#include "assets/gltf_import.hpp"
#include "assets/obj_import.hpp"

namespace atrium::assets {
namespace {

const ModelFormat* format_of(const std::filesystem::path& path) {
  const std::string extension = lowercase_extension(path);
  for (const ModelFormat& format : model_formats()) {
    if (std::find(format.extensions.begin(), format.extensions.end(), extension) != format.extensions.end()) return &format;
  }
  return nullptr;
}

}  // namespace

std::span<const ModelFormat> model_formats() {
  // libassimp reads more than its row lists: these are the ones tested or
  // common among the scenes users bring.
  static const std::array<ModelFormat, 3> formats{
      ModelFormat{"glTF", {".gltf", ".glb"}, import_gltf},
      ModelFormat{"OBJ with its MTL", {".obj"}, import_obj},
      ModelFormat{"FBX and the other formats libassimp reads", {".fbx", ".dae", ".3ds", ".ply", ".stl", ".x", ".lwo", ".ase", ".off"},
                  import_assimp},
  };
  return formats;
}

std::string model_formats_text() {
  std::string text;
  for (const ModelFormat& format : model_formats()) {
    std::string extensions;
    for (const std::string_view extension : format.extensions) extensions += (extensions.empty() ? "" : ", ") + std::string(extension);
    text += (text.empty() ? "" : "; ") + std::string(format.name) + " (" + extensions + ")";
  }
  return text;
}

std::optional<MaterialConvention> material_convention(std::string_view name) {
  if (name == "gltf") return MaterialConvention::Gltf;
  if (name == "bistro") return MaterialConvention::Bistro;
  if (name == "phong") return MaterialConvention::Phong;
  return std::nullopt;
}

bool is_model_file(const std::filesystem::path& path) { return format_of(path) != nullptr; }

ModelImport import_model(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  const ModelFormat* format = format_of(path);
  if (!format) throw ImportError(path.string() + ": not a model file Atrium reads (" + model_formats_text() + ")");
  return format->import(path, assets, options);
}

}  // namespace atrium::assets
