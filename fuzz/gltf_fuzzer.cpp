// libFuzzer target: glTF import, CPU side (no GL): JSON glTF, or binary glTF
// when the input starts with the "glTF" magic, with its meshopt and Draco
// decoders. Any input must import or be refused with ImportError; anything
// else is a bug.
#include <cstring>

#include "assets/gltf_import.hpp"
#include "assets/scene_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = atrium::fuzz::write_input(data, size, binary ? ".glb" : ".gltf");
  try {
    atrium::assets::AssetManager assets;
    // Sizes beyond 1 GiB are refused before allocating, as a user's load is
    // refused beyond the memory available (the fuzzer stops at 2 GiB).
    atrium::assets::ImportOptions options;
    options.memory_limit = std::size_t{1} << 30;
    (void)atrium::assets::import_gltf(path, assets, options);
  } catch (const atrium::assets::ImportError&) {
  }
  return 0;
}
