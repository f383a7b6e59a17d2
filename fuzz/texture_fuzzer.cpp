// libFuzzer target: texture decoding, CPU side (no GL), as model files reach it
// (glTF images, OBJ/FBX texture files): DDS headers and their block levels (and
// the libsquish fallback decode of those blocks), PNG, JPEG and the rest
// through stb. Any input must decode or be refused with an error string.
#include <string>

#include "assets/dds.hpp"
#include "assets/texture_decode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  // 64 MiB: a texture's sizes are checked against the budget before decoding.
  const atrium::assets::DecodedTexture decoded = atrium::assets::decode_texture(bytes, atrium::assets::ColorSpace::Srgb, std::size_t{64} << 20);
  if (decoded.texture && decoded.texture->compressed) {
    std::string error;
    (void)atrium::assets::decode_blocks(*decoded.texture->compressed, error);
  }
  return 0;
}
