// The image decoders behind decode_texture, each to 8-bit RGBA. PNG and JPEG,
// the two formats glTF allows and most models use, are read natively by
// Debian's libspng and TurboJPEG (png_jpeg.cpp), which are fuzzed upstream:
// Debian's stb_image (2.27) faults on hostile ones (a JPEG Huffman code
// outside its table reads before its arrays, found by the texture fuzzer with
// stb built in). The page has neither library and reads them with stb_image
// (web/png_jpeg.cpp); TGA, BMP, PGM and PPM go to stb_image in both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "assets/image.hpp"

namespace atrium::assets {

[[nodiscard]] bool is_png(std::span<const std::uint8_t> bytes);
[[nodiscard]] bool is_jpeg(std::span<const std::uint8_t> bytes);

// The picture as RGBA (grey spread to RGB, opaque where the file has no
// alpha), or nullopt with `error` saying why. Colour-space chunks and markers
// (gAMA, iCCP, sRGB) are ignored, as glTF asks: the material says what the
// values mean. A picture whose RGBA would pass `memory_limit` is refused before
// it is decoded.
[[nodiscard]] std::optional<Image> decode_png(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error);
[[nodiscard]] std::optional<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error);

// TGA, BMP and 8-bit binary PGM and PPM (and, in the page, PNG and JPEG).
[[nodiscard]] std::optional<Image> decode_with_stb(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error);

// "WxH needs N, more than the M of memory available", or empty when its RGBA
// fits: every decoder checks the size its header declares with this.
[[nodiscard]] std::string decoded_size_error(std::uint64_t width, std::uint64_t height, std::size_t memory_limit);

}  // namespace atrium::assets
