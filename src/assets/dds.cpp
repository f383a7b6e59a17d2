#include "assets/dds.hpp"

#include <algorithm>
#include <bit>
#include <cctype>

#include "assets/byte_order.hpp"
#include "base/mip_levels.hpp"

namespace atrium::assets {
namespace {

constexpr std::uint32_t fourcc(char a, char b, char c, char d) {
  return static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b) << 8 | static_cast<std::uint32_t>(c) << 16 |
         static_cast<std::uint32_t>(d) << 24;
}

constexpr std::size_t kHeaderBytes = 4 + 124;  // "DDS " and DDS_HEADER
constexpr std::size_t kDx10Bytes = 20;
constexpr std::uint32_t kFlagMipMapCount = 0x20000;
constexpr std::uint32_t kPixelAlpha = 0x1, kPixelFourCC = 0x4, kPixelRgb = 0x40, kPixelLuminance = 0x20000;
constexpr std::uint32_t kCaps2Cubemap = 0x200, kCaps2Volume = 0x200000;
constexpr std::uint32_t kDx10Texture2D = 3, kDx10MiscCube = 0x4;
constexpr int kMaxSide = 65536;

// DDS is little-endian whatever the host is.
std::uint32_t word(std::span<const std::uint8_t> bytes, std::size_t offset) { return static_cast<std::uint32_t>(read_le(bytes, offset, 4)); }

struct Layout {
  std::optional<BlockFormat> blocks;
  bool srgb = false;
  // Uncompressed: bits per pixel and the channel masks (a zero mask: 0, or 255 for alpha).
  std::uint32_t bits = 0;
  std::uint32_t masks[4] = {0, 0, 0, 0};
  bool luminance = false;
};

std::optional<Layout> dxgi_layout(std::uint32_t dxgi) {
  Layout l;
  switch (dxgi) {
    case 71: l.blocks = BlockFormat::BC1; break;
    case 72: l.blocks = BlockFormat::BC1; l.srgb = true; break;
    case 74: l.blocks = BlockFormat::BC2; break;
    case 75: l.blocks = BlockFormat::BC2; l.srgb = true; break;
    case 77: l.blocks = BlockFormat::BC3; break;
    case 78: l.blocks = BlockFormat::BC3; l.srgb = true; break;
    case 80: l.blocks = BlockFormat::BC4; break;
    case 83: l.blocks = BlockFormat::BC5; break;
    case 98: l.blocks = BlockFormat::BC7; break;
    case 99: l.blocks = BlockFormat::BC7; l.srgb = true; break;
    case 28: case 29:  // R8G8B8A8_UNORM(_SRGB)
      l.bits = 32;
      l.masks[0] = 0xff; l.masks[1] = 0xff00; l.masks[2] = 0xff0000; l.masks[3] = 0xff000000u;
      l.srgb = dxgi == 29;
      break;
    case 87: case 91: case 88:  // B8G8R8A8_UNORM(_SRGB), B8G8R8X8_UNORM
      l.bits = 32;
      l.masks[0] = 0xff0000; l.masks[1] = 0xff00; l.masks[2] = 0xff; l.masks[3] = dxgi == 88 ? 0 : 0xff000000u;
      l.srgb = dxgi == 91;
      break;
    default: return std::nullopt;
  }
  return l;
}

// A channel of an uncompressed pixel scaled to 8 bits.
std::uint8_t channel(std::uint32_t pixel, std::uint32_t mask, std::uint8_t missing) {
  if (mask == 0) return missing;
  const int shift = std::countr_zero(mask);
  const std::uint32_t max = mask >> shift;
  return static_cast<std::uint8_t>(((pixel & mask) >> shift) * 255u / max);
}

}  // namespace

std::size_t block_bytes(BlockFormat format) { return format == BlockFormat::BC1 || format == BlockFormat::BC4 ? 8 : 16; }

const char* block_format_name(BlockFormat format) {
  static const char* const kNames[] = {"BC1", "BC2", "BC3", "BC4", "BC5", "BC7"};
  return kNames[static_cast<int>(format)];
}

std::size_t CompressedImage::bytes() const {
  std::size_t total = 0;
  for (const auto& level : levels) total += level.size();
  return total;
}

bool is_dds(std::span<const std::uint8_t> bytes) { return bytes.size() >= 4 && word(bytes, 0) == fourcc('D', 'D', 'S', ' '); }

std::optional<DdsTexture> read_dds(std::span<const std::uint8_t> bytes, std::string& error) {
  auto fail = [&](std::string why) -> std::optional<DdsTexture> {
    error = std::move(why);
    return std::nullopt;
  };
  if (!is_dds(bytes) || bytes.size() < kHeaderBytes || word(bytes, 4) != 124) return fail("not a DDS file (no 124-byte header)");
  const std::uint32_t flags = word(bytes, 8);
  const int height = static_cast<int>(word(bytes, 12)), width = static_cast<int>(word(bytes, 16));
  std::uint32_t mips = (flags & kFlagMipMapCount) ? word(bytes, 28) : 1;
  const std::uint32_t pixel_flags = word(bytes, 80), code = word(bytes, 84);
  const std::uint32_t caps2 = word(bytes, 112);
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide) {
    return fail("a DDS of " + std::to_string(width) + "x" + std::to_string(height) + " pixels, outside 1 to " + std::to_string(kMaxSide));
  }
  if (caps2 & kCaps2Cubemap) return fail("a DDS cube map, which Atrium does not read");
  if (caps2 & kCaps2Volume) return fail("a DDS volume texture, which Atrium does not read");
  std::size_t offset = kHeaderBytes;
  Layout layout;
  if ((pixel_flags & kPixelFourCC) && code == fourcc('D', 'X', '1', '0')) {
    if (bytes.size() < kHeaderBytes + kDx10Bytes) return fail("a truncated DDS (no DX10 header)");
    const std::uint32_t dxgi = word(bytes, offset), dimension = word(bytes, offset + 4), misc = word(bytes, offset + 8);
    const std::uint32_t array_size = word(bytes, offset + 12);
    if (dimension != kDx10Texture2D) return fail("a DDS that is not a 2D texture (dimension " + std::to_string(dimension) + ")");
    if (misc & kDx10MiscCube) return fail("a DDS cube map, which Atrium does not read");
    if (array_size > 1) return fail("a DDS texture array, which Atrium does not read");
    const auto found = dxgi_layout(dxgi);
    if (!found) return fail("a DDS in DXGI format " + std::to_string(dxgi) + ", which Atrium does not read");
    layout = *found;
    offset += kDx10Bytes;
  } else if (pixel_flags & kPixelFourCC) {
    if (code == fourcc('D', 'X', 'T', '1')) layout.blocks = BlockFormat::BC1;
    else if (code == fourcc('D', 'X', 'T', '2') || code == fourcc('D', 'X', 'T', '3')) layout.blocks = BlockFormat::BC2;
    else if (code == fourcc('D', 'X', 'T', '4') || code == fourcc('D', 'X', 'T', '5')) layout.blocks = BlockFormat::BC3;
    else if (code == fourcc('A', 'T', 'I', '1') || code == fourcc('B', 'C', '4', 'U')) layout.blocks = BlockFormat::BC4;
    else if (code == fourcc('A', 'T', 'I', '2') || code == fourcc('B', 'C', '5', 'U')) layout.blocks = BlockFormat::BC5;
    else {
      std::string name(bytes.begin() + 84, bytes.begin() + 88);
      for (char& c : name) c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
      return fail("a DDS in the format '" + name + "', which Atrium does not read");
    }
  } else if (pixel_flags & (kPixelRgb | kPixelLuminance)) {
    layout.bits = word(bytes, 88);
    if (layout.bits != 8 && layout.bits != 16 && layout.bits != 24 && layout.bits != 32) {
      return fail("an uncompressed DDS of " + std::to_string(layout.bits) + " bits per pixel, which Atrium does not read");
    }
    layout.luminance = (pixel_flags & kPixelLuminance) != 0;
    for (int c = 0; c < 3; ++c) layout.masks[c] = word(bytes, 92 + 4 * static_cast<std::size_t>(c));
    layout.masks[3] = (pixel_flags & kPixelAlpha) ? word(bytes, 104) : 0;
  } else {
    return fail("a DDS whose pixel format names no layout Atrium reads");
  }
  mips = std::clamp<std::uint32_t>(mips, 1, static_cast<std::uint32_t>(mip_levels(width, height)));

  DdsTexture texture;
  texture.srgb = layout.srgb;
  if (layout.blocks) {
    CompressedImage image;
    image.format = *layout.blocks;
    image.width = width;
    image.height = height;
    for (std::uint32_t level = 0; level < mips; ++level) {
      const std::size_t w = std::max(1, width >> level), h = std::max(1, height >> level);
      const std::size_t size = ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(image.format);
      if (size > bytes.size() - offset) {
        if (level == 0) return fail("a truncated DDS (its first level needs " + std::to_string(size) + " bytes)");
        break;  // a short mip chain: upload what is there, the rest is generated
      }
      image.levels.emplace_back(bytes.begin() + static_cast<std::ptrdiff_t>(offset), bytes.begin() + static_cast<std::ptrdiff_t>(offset + size));
      offset += size;
    }
    texture.compressed = std::move(image);
    return texture;
  }
  const std::size_t pixel_bytes = layout.bits / 8;
  const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * pixel_bytes;
  if (size > bytes.size() - offset) return fail("a truncated DDS (its first level needs " + std::to_string(size) + " bytes)");
  texture.rgba = Image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)};
  for (std::size_t i = 0; i < static_cast<std::size_t>(width) * static_cast<std::size_t>(height); ++i) {
    const auto pixel = static_cast<std::uint32_t>(read_le(bytes, offset + i * pixel_bytes, pixel_bytes));
    std::uint8_t* out = &texture.rgba.rgba[i * 4];
    for (int c = 0; c < 3; ++c) {
      out[c] = channel(pixel, layout.luminance ? layout.masks[0] : layout.masks[c], 0);
    }
    out[3] = channel(pixel, layout.masks[3], 255);
  }
  return texture;
}

}  // namespace atrium::assets
