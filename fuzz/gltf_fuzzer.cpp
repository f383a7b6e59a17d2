// libFuzzer target: glTF import, CPU side (no GL): JSON glTF, or binary glTF
// when the input starts with the "glTF" magic. Any input must import or be
// refused with ImportError; anything else is a bug.
#include <cstring>

#include "assets/scene_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = atrium::fuzz::write_input(data, size, binary ? ".glb" : ".gltf");
  try {
    atrium::assets::AssetManager assets;
    (void)atrium::assets::import_gltf(path, assets);
  } catch (const atrium::assets::ImportError&) {
  }
  return 0;
}
