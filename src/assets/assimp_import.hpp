// Model files other than glTF and OBJ (FBX and the rest Debian's libassimp
// reads) into the same MeshAsset, materials and instances glTF import fills.
// Units become metres (FBX files say theirs). Materials follow the convention
// asked for (model_import.hpp, classic_materials.hpp).
// Texture paths as exporters write them are found: Windows separators, another
// letter case than on disk, absolute paths from the author's machine (looked
// up beside the model and in the folders below it), each with one warning.
// Textures decode on worker threads (PNG, JPEG, TGA, DDS, ...), DDS blocks stay
// compressed.
#pragma once

#include <filesystem>

#include "assets/model_import.hpp"

namespace atrium::assets {

// Throws ImportError("<path>: <problem>") when the file cannot be used.
[[nodiscard]] ModelImport import_assimp(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options = {});

}  // namespace atrium::assets
