// libFuzzer target: OBJ (tinyobjloader, compiled in) and FBX (libassimp,
// through Atrium's own file access, assets/assimp_file_access.hpp). Binary FBX
// when the input starts with its magic, else OBJ; the same bytes are also
// written as the OBJ's material library `input.mtl`, so an input that names it
// is parsed both ways. Any input
// must import or be refused with ImportError; anything else is a bug.
#include <cstring>

#include "assets/model_import.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static constexpr char kFbxMagic[] = "Kaydara FBX Binary";
  const bool fbx = size >= sizeof kFbxMagic - 1 && std::memcmp(data, kFbxMagic, sizeof kFbxMagic - 1) == 0;
  (void)atrium::fuzz::write_input(data, size, ".mtl");
  const auto path = atrium::fuzz::write_input(data, size, fbx ? ".fbx" : ".obj");
  try {
    atrium::assets::AssetManager assets;
    atrium::assets::ImportOptions options;
    options.memory_limit = std::size_t{1} << 30;
    (void)atrium::assets::import_model(path, assets, options);
  } catch (const atrium::assets::ImportError&) {
  }
  return 0;
}
