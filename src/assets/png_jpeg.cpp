#include "assets/image_decoders.hpp"

#include <algorithm>
#include <limits>
#include <memory>

#include <spng.h>
#include <turbojpeg.h>

namespace atrium::assets {

std::optional<Image> decode_png(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error) {
  const std::unique_ptr<spng_ctx, decltype(&spng_ctx_free)> png(spng_ctx_new(0), spng_ctx_free);
  if (!png) {
    error = "out of memory while starting the PNG decoder";
    return std::nullopt;
  }
  // Text, ICC and other ancillary chunks are held in memory too: the same
  // limit, a chunk's at most the 2^31 - 1 bytes libspng takes (it refuses
  // a larger value and keeps its default).
  spng_set_chunk_limits(png.get(), std::min<std::size_t>(memory_limit, std::numeric_limits<std::int32_t>::max()), memory_limit);
  spng_ihdr header{};
  int status = spng_set_png_buffer(png.get(), bytes.data(), bytes.size());
  if (status == 0) status = spng_get_ihdr(png.get(), &header);
  if (status != 0) {
    error = std::string("not a readable PNG: ") + spng_strerror(status);
    return std::nullopt;
  }
  if (error = decoded_size_error(header.width, header.height, memory_limit); !error.empty()) return std::nullopt;
  std::size_t size = 0;
  status = spng_decoded_image_size(png.get(), SPNG_FMT_RGBA8, &size);
  Image image{static_cast<int>(header.width), static_cast<int>(header.height), {}};
  if (status == 0) {
    image.rgba.resize(size);
    // No SPNG_DECODE_GAMMA: the file's gamma is ignored, as glTF asks.
    status = spng_decode_image(png.get(), image.rgba.data(), size, SPNG_FMT_RGBA8, SPNG_DECODE_TRNS);
  }
  if (status != 0) {
    error = std::string("a damaged PNG: ") + spng_strerror(status);
    return std::nullopt;
  }
  return image;
}

std::optional<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::size_t memory_limit, std::string& error) {
  const std::unique_ptr<void, decltype(&tjDestroy)> jpeg(tjInitDecompress(), tjDestroy);
  if (!jpeg) {
    error = "out of memory while starting the JPEG decoder";
    return std::nullopt;
  }
  int width = 0, height = 0, subsampling = 0, colour_space = 0;
  const unsigned long size = bytes.size();
  // Warnings (a few stray bytes, a truncated end) leave a usable picture, as
  // in every viewer; only a fatal error refuses the file.
  const auto failed = [&](int status) { return status != 0 && tjGetErrorCode(jpeg.get()) == TJERR_FATAL; };
  if (failed(tjDecompressHeader3(jpeg.get(), bytes.data(), size, &width, &height, &subsampling, &colour_space))) {
    error = std::string("not a readable JPEG: ") + tjGetErrorStr2(jpeg.get());
    return std::nullopt;
  }
  if (error = decoded_size_error(static_cast<std::uint64_t>(width), static_cast<std::uint64_t>(height), memory_limit); !error.empty()) {
    return std::nullopt;
  }
  // TurboJPEG gives CMYK files only as CMYK; they are turned into RGB below.
  const bool cmyk = colour_space == TJCS_CMYK || colour_space == TJCS_YCCK;
  Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)};
  // LIMITSCANS: a progressive file of thousands of scans would take minutes.
  if (failed(tjDecompress2(jpeg.get(), bytes.data(), size, image.rgba.data(), width, width * 4, height, cmyk ? TJPF_CMYK : TJPF_RGBA,
                           TJFLAG_LIMITSCANS))) {
    error = std::string("a damaged JPEG: ") + tjGetErrorStr2(jpeg.get());
    return std::nullopt;
  }
  if (cmyk) {
    // Adobe's CMYK files store ink inverted (255 = none), so each colour is
    // its inverted ink darkened by the inverted black.
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      const unsigned k = image.rgba[i + 3];
      for (std::size_t c = 0; c < 3; ++c) image.rgba[i + c] = static_cast<std::uint8_t>((image.rgba[i + c] * k + 127) / 255);
      image.rgba[i + 3] = 255;
    }
  }
  return image;
}

}  // namespace atrium::assets
