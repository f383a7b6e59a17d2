// glTF 2.0 import (.gltf and .glb) through tinygltf, CPU only: meshes,
// materials, textures, the node hierarchy and KHR_lights_punctual lights become
// a MeshAsset in the AssetManager plus instances and lights for a scene. Images
// decode on worker threads. Broken files fail with an ImportError naming the
// file and the problem; recoverable trouble (an undecodable image, an unknown
// optional extension, a non-triangle primitive) becomes a warning.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "assets/asset_manager.hpp"
#include "assets/progress.hpp"
#include "assets/scene.hpp"

namespace atrium::assets {

class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// glTF's photometric light units to Atrium's: point and spot intensities in
// candela (lm/sr) and directional illuminance in lux divide by 683 lm/W, the
// luminous efficacy that defines the candela. Atrium's intensity is radiant
// intensity (W/sr) for point and spot lights and irradiance (W/m^2) for
// directional ones, so a 100 W isotropic Blender light (683*100/4pi cd in its
// glTF) arrives as 100/4pi = 7.96.
inline constexpr float kLumensPerWatt = 683.0f;

struct ImportTimings {
  double parse_seconds = 0.0;   // JSON, buffers, accessors, meshes
  double decode_seconds = 0.0;  // image decoding (worker threads)
};

struct GltfImport {
  MeshAssetHandle asset;
  std::vector<SceneInstance> instances;  // one per node that has a mesh
  std::vector<SceneLight> lights;        // KHR_lights_punctual, placed by their nodes
  glm::vec3 bounds_min{0.0f};            // of all instances, world space
  glm::vec3 bounds_max{0.0f};
  std::vector<std::string> warnings;     // each names the file
  ImportTimings timings;
  std::size_t images = 0;
};

// Throws ImportError("<path>: <problem>") when the file cannot be used.
struct ImportOptions {
  ProgressCallback progress;     // hears about image decoding as it happens
  unsigned decode_threads = 0;   // 0: one per core (at most 16)
};

[[nodiscard]] GltfImport import_gltf(const std::filesystem::path& path, AssetManager& assets,
                                     const ImportOptions& options = {});

// Extensions whose presence in extensionsRequired is accepted.
[[nodiscard]] const std::vector<std::string>& supported_gltf_extensions();

}  // namespace atrium::assets
