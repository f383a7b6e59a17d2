// Wavefront OBJ with its MTL material libraries into the same MeshAsset,
// materials and instances glTF import fills, parsed by Debian's tinyobjloader
// in the native and the browser build alike (the page has no libassimp). OBJ
// has no units: it is read as metres, +Y up, its texture V pointing up.
// Materials follow the convention asked for (Phong unless told otherwise:
// classic_materials.hpp); material libraries and textures are found as
// exporters write their paths (file_lookup.hpp), each with one warning when
// not where the path says or not readable.
#pragma once

#include <filesystem>

#include "assets/model_import.hpp"

namespace atrium::assets {

// tinyobjloader cuts a face of more than four corners into triangles by ear
// clipping, whose cost grows with the square of its corners (a 16,384-gon:
// 0.6 s; 1,000 copies of a 1,024-gon in a 4 MiB file: 2.5 s, on one core of
// the 2-core CI machine). A file whose faces' corners, squared and summed,
// exceed this is refused before it is parsed: about 2.5 s of cutting there,
// and far beyond real exports (a million 16-gons is a quarter of it).
inline constexpr std::size_t kMaxObjClipWork = std::size_t{1} << 30;

// Throws ImportError("<path>: <problem>") when the file cannot be used.
[[nodiscard]] ModelImport import_obj(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options = {});

}  // namespace atrium::assets
