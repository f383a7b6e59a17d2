#include "assets/texture_decode.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <mutex>
#include <new>
#include <string>
#include <string_view>

#include <stb_image.h>

#include "assets/dds.hpp"
#include "assets/image_decoders.hpp"
#include "assets/byte_order.hpp"
#include "assets/load_budget.hpp"
#include "base/parallel.hpp"

namespace atrium::assets {
namespace {

// A PNG (its signature checked) whose chunk claims more bytes than the file
// holds, or an empty string. stb_image (the page's PNG reader) trusts IDAT
// lengths and grows its buffer to fit them: a 33 KB file claiming a 1 GB
// chunk would allocate gigabytes before finding the data missing (found by
// the texture fuzzer). libspng refuses it too, as "invalid scanline filter";
// this names the chunk.
std::string png_chunk_error(std::span<const std::uint8_t> bytes) {
  std::size_t at = 8;
  while (bytes.size() - at >= 8) {
    const std::uint32_t length = (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
                                 (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
    const std::string type(reinterpret_cast<const char*>(bytes.data() + at + 4), 4);
    const std::size_t remaining = bytes.size() - at - 8;
    // Length, type, data and a four-byte CRC.
    if (std::size_t{length} + 4 > remaining) {
      return "PNG chunk '" + type + "' claims " + std::to_string(length) + " bytes but the file holds " +
             std::to_string(remaining < 4 ? 0 : remaining - 4) + " more";
    }
    if (type == "IEND") break;
    at += 12 + std::size_t{length};
  }
  return {};
}

// Why stb_image must not read this binary PGM or PPM, or an empty string: its
// header is read here as stb_image reads it (whitespace, '#' comments to the
// end of the line, then width, height and the largest sample value).
// - A number beyond 2^31 - 1 overflows stb_image's int (undefined behaviour,
//   found by the texture fuzzer once stb was compiled into it).
// - More than 8 bits a sample: Debian's stb_image (2.27) reads those samples
//   in the wrong byte order, and asked for RGBA it converts them with its
//   8-bit converter and reads past its buffer (found by the texture fuzzer;
//   ImageMagick's 16-bit files do both).
std::string pnm_header_error(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '6')) return {};
  const auto space = [](std::uint8_t c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
  std::size_t at = 2;
  std::uint64_t value = 0;
  for (int field = 0; field < 3; ++field) {
    while (at < bytes.size() && (space(bytes[at]) || bytes[at] == '#')) {
      while (at < bytes.size() && space(bytes[at])) ++at;
      if (at < bytes.size() && bytes[at] == '#') {
        while (at < bytes.size() && bytes[at] != '\n' && bytes[at] != '\r') ++at;
      }
    }
    for (value = 0; at < bytes.size() && bytes[at] >= '0' && bytes[at] <= '9'; ++at) {
      value = value * 10 + (bytes[at] - '0');
      if (value > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) return "a PGM or PPM header number beyond 2147483647";
    }
  }
  if (value > 255) return "16-bit PGM and PPM images are not read, as stb_image misreads them: save it with 8 bits a sample or as PNG";
  return {};
}

// Why stb_image cannot read this BMP, or an empty string: it reads BMPs whose
// pixels are stored plain or under bit masks, but not run-length encoded (RLE8,
// RLE4) or holding a JPEG or PNG, which it would call an "unknown image type".
// The compression is the word at byte 30 of every header since Windows 3's
// (40 bytes or more, its size at byte 14); OS/2's 12-byte header has none.
std::string bmp_compression_error(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 34 || bytes[0] != 'B' || bytes[1] != 'M') return {};
  if (read_le(bytes, 14, 4) < 40) return {};
  switch (read_le(bytes, 30, 4)) {
    case 1: case 2: return "run-length encoded BMP images are not read: save it uncompressed or as PNG";
    case 4: case 5: return "BMP images holding a JPEG or PNG are not read: save that JPEG or PNG itself";
    default: return {};
  }
}

// Formats stb_image reads that Atrium does not take as textures: none is a
// texture format of glTF or of the models Atrium imports, and stb_image's
// readers of them are the least safe it has (its GIF reader has open
// memory-safety reports upstream; its HDR reader took over 20 s on small
// files the texture fuzzer wrote).
struct RefusedFormat {
  const char* name;
  std::string_view magic;
};
constexpr RefusedFormat kRefusedFormats[] = {
    {"GIF", "GIF8"},
    {"Photoshop (PSD)", "8BPS"},
    {"Radiance HDR", "#?RADIANCE"},
    {"Radiance HDR", "#?RGBE"},
    {"Softimage PIC", "\x53\x80\xf6\x34"},
};

const RefusedFormat* refused_format(std::span<const std::uint8_t> bytes) {
  for (const RefusedFormat& format : kRefusedFormats) {
    if (bytes.size() >= format.magic.size() && std::equal(format.magic.begin(), format.magic.end(), bytes.begin(),
                                                          [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; })) {
      return &format;
    }
  }
  return nullptr;
}

}  // namespace

bool is_png(std::span<const std::uint8_t> bytes) {
  constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return bytes.size() >= 8 && std::equal(kSignature, kSignature + 8, bytes.begin());
}

// As stb_image knows a JPEG: a start-of-image marker after any number of 0xff
// fill bytes. Every file it would take for one must go to decode_jpeg, never
// to stb_image's JPEG reader (TurboJPEG refuses those that do not start
// 0xff 0xd8).
bool is_jpeg(std::span<const std::uint8_t> bytes) {
  if (bytes.empty() || bytes[0] != 0xff) return false;
  std::size_t at = 1;
  while (at < bytes.size() && bytes[at] == 0xff) ++at;
  return at < bytes.size() && bytes[at] == 0xd8;
}

std::string decoded_size_error(std::uint64_t width, std::uint64_t height, std::size_t memory_limit) {
  const double decoded_bytes = static_cast<double>(width) * static_cast<double>(height) * 4;
  if (decoded_bytes <= static_cast<double>(memory_limit)) return {};
  return std::to_string(width) + "x" + std::to_string(height) + " needs " + format_bytes(decoded_bytes) + ", more than the " +
         format_bytes(static_cast<double>(memory_limit)) + " of memory available";
}

std::optional<Image> decode_with_stb(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error) {
  if (const RefusedFormat* format = refused_format(bytes)) {
    error = std::string(format->name) + " images are not read as textures, only " + kTextureFormats + ": save it as PNG";
    return std::nullopt;
  }
  if (error = pnm_header_error(bytes); !error.empty()) return std::nullopt;
  if (error = bmp_compression_error(bytes); !error.empty()) return std::nullopt;
  int width = 0, height = 0, channels = 0;
  const int size = static_cast<int>(bytes.size());
  if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &channels)) {
    error = stbi_failure_reason();
    return std::nullopt;
  }
  if (error = decoded_size_error(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height), memory_limit); !error.empty()) {
    return std::nullopt;
  }
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &width, &height, &channels, 4);
  if (!pixels) {
    error = stbi_failure_reason();
    return std::nullopt;
  }
  Image image{width, height, std::vector<std::uint8_t>(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)};
  stbi_image_free(pixels);
  return image;
}

DecodedTexture decode_texture(std::span<const std::uint8_t> bytes, ColorSpace space, std::size_t memory_limit) {
  DecodedTexture result;
  if (bytes.empty()) {
    result.error = "no image data";
    return result;
  }
  try {
    if (is_dds(bytes)) {
      std::optional<DdsTexture> dds = read_dds(bytes, result.error);
      if (!dds) return result;
      TextureData texture;
      texture.color_space = space;
      if (dds->compressed) texture.compressed = std::move(*dds->compressed);
      else texture.image = std::move(dds->rgba);
      result.texture = std::move(texture);
      return result;
    }
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      result.error = "the image file is larger than 2 GiB";
      return result;
    }
    std::optional<Image> image;
    if (is_png(bytes)) {
      result.error = png_chunk_error(bytes);
      if (result.error.empty()) image = decode_png(bytes, memory_limit, result.error);
    } else if (is_jpeg(bytes)) {
      image = decode_jpeg(bytes, memory_limit, result.error);
    } else {
      image = decode_with_stb(bytes, memory_limit, result.error);
    }
    if (!image) return result;
    TextureData texture;
    texture.color_space = space;
    texture.image = std::move(*image);
    result.texture = std::move(texture);
  } catch (const std::bad_alloc&) {
    result.error = "out of memory while decoding it";
    result.texture.reset();
  }
  return result;
}

std::vector<DecodedTexture> decode_in_parallel(std::size_t count, const std::function<DecodedTexture(std::size_t)>& decode,
                                               unsigned threads, const ProgressCallback& progress) {
  std::vector<DecodedTexture> results(count);
  std::atomic<std::size_t> next{0}, finished{0};
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      if (progress && i > 0) {
        std::lock_guard lock(progress_mutex);
        progress("decoding images", finished.load(), count);
      }
      try {
        results[i] = decode(i);
      } catch (const std::bad_alloc&) {
        results[i] = {std::nullopt, "out of memory while decoding it"};
      }
      ++finished;
    }
  };
  const unsigned wanted = threads ? threads : std::clamp<unsigned>(hardware_threads(), 1, 16);
  run_in_parallel(std::max<std::size_t>(1, std::min<std::size_t>(wanted, count)), [&](std::size_t) { worker(); });
  return results;
}

}  // namespace atrium::assets
