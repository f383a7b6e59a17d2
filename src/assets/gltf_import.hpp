// glTF 2.0 import (.gltf and .glb), CPU only: the checked document
// (gltf_document.hpp) becomes a MeshAsset in the AssetManager plus instances
// and lights for a scene. Compressed geometry is decoded (gltf_compression.hpp),
// primitives that share vertex accessors share one vertex buffer, and
// EXT_mesh_gpu_instancing instances become instances. Images decode on worker
// threads. Broken files fail with an ImportError naming the file and the
// problem; recoverable trouble (an undecodable image, an optional extension
// Atrium cannot use, a point or line primitive) becomes a warning.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "assets/asset_manager.hpp"
#include "assets/gltf_document.hpp"
#include "assets/progress.hpp"
#include "assets/scene.hpp"

namespace atrium::assets {

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
  // One per node that has a mesh, and one per EXT_mesh_gpu_instancing instance.
  std::vector<SceneInstance> instances;
  std::vector<SceneLight> lights;        // KHR_lights_punctual, placed by their nodes
  // Of every instance's triangles, world space; a zero box at the origin when
  // the model has none (`empty`).
  glm::vec3 bounds_min{0.0f};
  glm::vec3 bounds_max{0.0f};
  bool empty = true;
  std::vector<std::string> warnings;     // each names the file
  ImportTimings timings;
  std::size_t images = 0;
};

// Throws ImportError("<path>: <problem>") when the file cannot be used.
struct ImportOptions {
  ProgressCallback progress;     // hears about image decoding as it happens
  unsigned decode_threads = 0;   // 0: one per core (at most 16)
  // The largest single allocation a load may make (the file's sizes are
  // checked against it first); 0: the memory the system has available.
  std::size_t memory_limit = 0;
};

[[nodiscard]] GltfImport import_gltf(const std::filesystem::path& path, AssetManager& assets,
                                     const ImportOptions& options = {});


}  // namespace atrium::assets
