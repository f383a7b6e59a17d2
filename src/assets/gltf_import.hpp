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

#include "assets/model_import.hpp"

namespace atrium::assets {

// Throws ImportError("<path>: <problem>") when the file cannot be used.
[[nodiscard]] ModelImport import_gltf(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options = {});

}  // namespace atrium::assets
