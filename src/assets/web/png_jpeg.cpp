// The page's PNG and JPEG reader: stb_image, compiled from Debian's headers
// (web/stb.cpp), since the page has no libspng or TurboJPEG (emscripten would
// download its ports while building). Its known faults on hostile JPEGs stay
// here, inside the browser's sandbox: docs/scene-format.md says so.
#include "assets/image_decoders.hpp"

namespace atrium::assets {

std::optional<Image> decode_png(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error) {
  return decode_with_stb(bytes, memory_limit, error);
}

std::optional<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error) {
  return decode_with_stb(bytes, memory_limit, error);
}

}  // namespace atrium::assets
