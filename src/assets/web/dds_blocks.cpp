// decode_blocks for the WebAssembly build, which has no libsquish: a DDS whose
// blocks the browser cannot sample is refused with one line (the native build
// decodes BC1-BC5 in assets/dds_blocks.cpp).
#include "assets/dds.hpp"

namespace atrium::assets {

std::optional<Image> decode_blocks(const CompressedImage&, std::string& error) {
  error = "block-compressed, which this browser cannot sample and the browser build cannot decode (no libsquish)";
  return std::nullopt;
}

}  // namespace atrium::assets
