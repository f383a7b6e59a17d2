// One texture file's bytes to TextureData, for every importer: PNG, JPEG, TGA,
// BMP, 8-bit PGM and PPM (image_decoders.hpp says which library reads which),
// and DDS (dds.hpp), whose block-compressed levels stay compressed. The
// decoded size is checked against `memory_limit` before decoding.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "assets/asset_manager.hpp"
#include "assets/progress.hpp"

namespace atrium::assets {

// What decode_texture reads, as its refusals name it.
inline constexpr const char* kTextureFormats = "PNG, JPEG, TGA, BMP, 8-bit PGM and PPM, and DDS";

struct DecodedTexture {
  std::optional<TextureData> texture;  // its name is left for the caller
  std::string error;                   // why not, when texture is empty
};

[[nodiscard]] DecodedTexture decode_texture(std::span<const std::uint8_t> bytes, ColorSpace space, std::size_t memory_limit);

// decode(i) for every i below `count` on worker threads (0: one per core, at
// most 16), in order of i; `progress` hears "decoding images" as they finish.
[[nodiscard]] std::vector<DecodedTexture> decode_in_parallel(std::size_t count, const std::function<DecodedTexture(std::size_t)>& decode,
                                                             unsigned threads, const ProgressCallback& progress);

}  // namespace atrium::assets
