// Materials as OBJ's MTL and FBX state them (diffuse colour, specular exponent,
// opacity, texture slots by name) into Atrium's metallic-roughness Material, by
// the convention asked for (model_import.hpp), and their textures found beside
// the model, decoded on worker threads and given their roles. Shared by the OBJ
// importer (obj_import.hpp) and libassimp's (assimp_import.hpp), so that a
// material reads the same whichever library parsed its file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/model_import.hpp"

namespace atrium::assets {

// What a file says of one material; absent values take the convention's default.
struct ClassicMaterial {
  std::string name;
  std::optional<glm::vec4> base_color;  // a PBR base colour, where the file has one
  glm::vec3 diffuse{1.0f};              // otherwise the diffuse colour
  float opacity = 1.0f;
  glm::vec3 emissive{0.0f};
  std::optional<float> shininess, metallic, roughness;  // Blinn-Phong exponent; PBR factors
  std::optional<bool> two_sided;
  // Texture paths as the file writes them, by slot. `normal` lists the slots
  // that may hold a normal map, first found wins (a bump slot's greyscale
  // height map is refused with a warning when decoded).
  std::optional<std::string> base_color_texture, normal_texture, emissive_texture, specular_texture, metalness_texture,
      roughness_texture, occlusion_texture, opacity_texture;
};

// Textures that the model file holds itself (FBX embeds them): whether a path
// as written names one (else it is a file path), and its bytes (empty with
// `error` set when it cannot be read).
struct EmbeddedTextures {
  std::function<bool(const std::string& written)> holds;
  std::function<std::vector<std::uint8_t>(const std::string& written, std::string& error)> read;
};

class ClassicMaterials {
 public:
  // Warnings go to `result` naming `model`; decoded textures count in result.images.
  ClassicMaterials(const std::filesystem::path& model, MaterialConvention convention, AssetManager& assets, const ImportOptions& options,
                   ModelImport& result);

  // The Material for `source`, to be materials[index]; its textures are
  // remembered for decode().
  [[nodiscard]] Material convert(const ClassicMaterial& source, std::size_t index);
  // The plain dielectric for geometry whose material is missing, added to
  // `asset` the first time it is asked for.
  [[nodiscard]] std::uint32_t default_material(MeshAsset& asset);
  // Finds and decodes every texture convert() was given and sets it in
  // `materials` by its role.
  void decode(std::vector<Material>& materials, const EmbeddedTextures& embedded = {});

 private:
  struct Wanted {
    std::size_t material;
    enum class Role { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive, Opacity } role;
    std::string path;  // as the file wrote it
    ColorSpace space;
  };

  void warn(const std::string& problem);
  std::optional<std::filesystem::path> find_texture(const std::string& written);
  void apply_opacity(Material& m, const std::string& what, const TextureData& opacity, const std::string& name);

  std::filesystem::path model_;
  std::string name_;
  MaterialConvention convention_;
  AssetManager& assets_;
  const ImportOptions& options_;
  ModelImport& result_;
  std::vector<Wanted> wanted_;
  std::map<std::string, std::optional<std::filesystem::path>> found_;
  std::optional<std::uint32_t> default_material_;
};

}  // namespace atrium::assets
