// What importing a model file gives, whatever its format: a MeshAsset in the
// AssetManager plus instances and lights for a scene, and what loading cost.
// import_model picks the importer by extension from one table, model_formats():
// glTF (.gltf, .glb) through gltf_import.hpp, OBJ with its MTL through
// obj_import.hpp, what Debian's libassimp reads (.fbx, .dae, ...) through
// assimp_import.hpp. A new format is its
// importer's file pair and one row; help and messages are built from the table.
#pragma once

#include "base/box.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset_manager.hpp"
#include "assets/load_budget.hpp"
#include "assets/progress.hpp"
#include "assets/scene.hpp"

namespace atrium::assets {

// How a model's materials map to Atrium's metallic-roughness inputs (a scene
// file's "materials" picks one per model; each format has its default).
enum class MaterialConvention : std::uint8_t {
  Gltf,    // metal-rough as glTF defines it (the default for glTF and FBX)
  Bistro,  // NVIDIA's Bistro: BaseColor (alpha = opacity), "Specular" = occlusion R,
           // roughness G, metalness B, DirectX normal maps
  Phong,   // diffuse, specular exponent, bump/normal and opacity maps (the default for OBJ)
};

// glTF's photometric light units to Atrium's: point and spot intensities in
// candela (lm/sr) and directional illuminance in lux divide by 683 lm/W, the
// luminous efficacy that defines the candela. Atrium's intensity is radiant
// intensity (W/sr) for point and spot lights and irradiance (W/m^2) for
// directional ones, so a 100 W isotropic Blender light (683*100/4pi cd in its
// glTF) arrives as 100/4pi = 7.96.
inline constexpr float kLumensPerWatt = 683.0f;

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct ImportTimings {
  double parse_seconds = 0.0;   // the file, its buffers and meshes
  double decode_seconds = 0.0;  // image decoding (worker threads)
};

struct ModelImport {
  MeshAssetHandle asset;
  // One per node and mesh it draws (and per EXT_mesh_gpu_instancing instance).
  std::vector<SceneInstance> instances;
  std::vector<SceneLight> lights;        // the file's lights, placed by their nodes
  // Of every instance's triangles, world space (empty: it has none).
  Box bounds;
  std::vector<std::string> warnings;     // each names the file
  ImportTimings timings;
  std::size_t images = 0;
};

struct ImportOptions {
  ProgressCallback progress;     // hears about image decoding as it happens
  // How to read materials; absent: the format's default.
  std::optional<MaterialConvention> convention;
  unsigned decode_threads = 0;   // 0: one per core (at most 16)
  // The largest single allocation a load may make (the file's sizes are
  // checked against it first); 0: the memory the system has available.
  std::size_t memory_limit = 0;
};

// "gltf", "bistro", "phong"; nullopt for another name.
[[nodiscard]] std::optional<MaterialConvention> material_convention(std::string_view name);

// A file format import_model reads: its name, its extensions (lower case,
// with the dot) and its importer (which throws ImportError naming the file).
struct ModelFormat {
  std::string_view name;
  std::vector<std::string_view> extensions;
  ModelImport (*import)(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options);
};
[[nodiscard]] std::span<const ModelFormat> model_formats();
// "glTF (.gltf, .glb); OBJ with its MTL (.obj); FBX and the other formats libassimp reads (.fbx, ...)".
[[nodiscard]] std::string model_formats_text();

// Whether the extension (in any letter case) is one of model_formats()'.
[[nodiscard]] bool is_model_file(const std::filesystem::path& path);

// Throws ImportError("<path>: <problem>") when the file cannot be used.
[[nodiscard]] ModelImport import_model(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options = {});

}  // namespace atrium::assets
