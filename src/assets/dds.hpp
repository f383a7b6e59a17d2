// DDS textures as DirectX tools and game pipelines write them (Bistro ships all
// its textures so): the legacy header with FourCC DXT1, DXT3, DXT5, ATI1/BC4U,
// ATI2/BC5U or uncompressed RGB(A) bit masks, and the DX10 header with the DXGI
// formats BC1-BC5 and BC7 (UNORM and SRGB) and 8-bit RGBA/BGRA; 2D textures
// with their mip chains. Every size the header declares is checked against the
// file. Block-compressed data stays compressed for upload (gpu_assets.cpp);
// decode_blocks turns it into RGBA for drivers that lack a format.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "assets/image.hpp"

namespace atrium::assets {

enum class BlockFormat : std::uint8_t { BC1, BC2, BC3, BC4, BC5, BC7 };

// Bytes per 4x4 block.
[[nodiscard]] std::size_t block_bytes(BlockFormat format);
[[nodiscard]] const char* block_format_name(BlockFormat format);

// A block-compressed texture: every mip level's blocks, largest first.
struct CompressedImage {
  BlockFormat format = BlockFormat::BC1;
  int width = 0;
  int height = 0;
  std::vector<std::vector<std::uint8_t>> levels;

  [[nodiscard]] std::size_t bytes() const;
};

// What a DDS file holds: block-compressed levels, or an uncompressed top level
// as RGBA8 (its mip chain is rebuilt on upload like any image's).
struct DdsTexture {
  std::optional<CompressedImage> compressed;
  Image rgba;
  bool srgb = false;  // a DXGI *_SRGB format: the file says its colour is sRGB-encoded
};

[[nodiscard]] bool is_dds(std::span<const std::uint8_t> bytes);
// nullopt with `error` set (one phrase: "a cube map, which Atrium does not read")
// when the file cannot be used.
[[nodiscard]] std::optional<DdsTexture> read_dds(std::span<const std::uint8_t> bytes, std::string& error);

// The top level of `image` as RGBA8 (libsquish decodes BC1-BC5); nullopt with
// `error` set for formats it cannot decode (BC7, which every GL 4.2 driver reads).
[[nodiscard]] std::optional<Image> decode_blocks(const CompressedImage& image, std::string& error);

}  // namespace atrium::assets
