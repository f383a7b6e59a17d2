// decode_blocks (assets/dds.hpp) through libsquish: BC1-BC5 blocks to RGBA8
// for drivers that cannot sample them. The WebAssembly build, without
// libsquish, has assets/web/dds_blocks.cpp instead.
#include <cstring>

#include <squish.h>

#include "assets/dds.hpp"

namespace atrium::assets {

namespace {

// BC4 and BC5 channels are DXT5 alpha blocks. libsquish 1.15 (Debian 12)
// decodes kBc4/kBc5 input as a colour block instead, so each channel goes
// through its DXT5 path as the alpha half of a block whose colour half is black.
void decode_alpha_channels(const CompressedImage& image, int channels, Image& out) {
  const std::uint8_t* blocks = image.levels.at(0).data();
  const int blocks_x = (image.width + 3) / 4, blocks_y = (image.height + 3) / 4;
  for (int by = 0; by < blocks_y; ++by) {
    for (int bx = 0; bx < blocks_x; ++bx) {
      for (int channel = 0; channel < channels; ++channel) {
        std::uint8_t dxt5[16] = {};
        std::memcpy(dxt5, blocks, 8);
        blocks += 8;
        std::uint8_t pixels[64];
        squish::Decompress(pixels, dxt5, squish::kDxt5);
        for (int y = 0; y < 4 && by * 4 + y < image.height; ++y) {
          for (int x = 0; x < 4 && bx * 4 + x < image.width; ++x) {
            std::uint8_t* texel = &out.rgba[(static_cast<std::size_t>(by * 4 + y) * static_cast<std::size_t>(image.width) +
                                             static_cast<std::size_t>(bx * 4 + x)) * 4];
            const std::uint8_t value = pixels[(y * 4 + x) * 4 + 3];
            // One channel reads as grey, as GL samples BC4 through the RED swizzle.
            if (channels == 1) texel[0] = texel[1] = texel[2] = value;
            else texel[channel] = value;
            texel[3] = 255;
          }
        }
      }
    }
  }
}

}  // namespace

std::optional<Image> decode_blocks(const CompressedImage& image, std::string& error) {
  Image out{image.width, image.height,
            std::vector<std::uint8_t>(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4)};
  switch (image.format) {
    case BlockFormat::BC1:
      squish::DecompressImage(out.rgba.data(), image.width, image.height, image.levels.at(0).data(), squish::kDxt1);
      return out;
    case BlockFormat::BC2:
      squish::DecompressImage(out.rgba.data(), image.width, image.height, image.levels.at(0).data(), squish::kDxt3);
      return out;
    case BlockFormat::BC3:
      squish::DecompressImage(out.rgba.data(), image.width, image.height, image.levels.at(0).data(), squish::kDxt5);
      return out;
    case BlockFormat::BC4: decode_alpha_channels(image, 1, out); return out;
    case BlockFormat::BC5: decode_alpha_channels(image, 2, out); return out;
    case BlockFormat::BC7:
      error = "BC7, which this driver cannot sample and Atrium cannot decode";
      return std::nullopt;
  }
  error = "an unknown block format";
  return std::nullopt;
}

}  // namespace atrium::assets
