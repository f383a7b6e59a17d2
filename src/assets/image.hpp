// 8-bit RGBA images on the CPU: rendered frames, decoded textures, and the
// metrics (PSNR, largest channel difference) that compare one picture to another.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace atrium::assets {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // rows top to bottom, 4 bytes per pixel

  [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4];
  }
};

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ImageError naming the file when it cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);
[[nodiscard]] Image read_png(const std::filesystem::path& path);

// `image` scaled down, keeping its aspect ratio, so that neither side exceeds
// `max_size`; filtered in linear light when `srgb` says the colour channels are
// sRGB-encoded (alpha is always linear). An image that fits comes back as is.
[[nodiscard]] Image downscale_to_fit(const Image& image, int max_size, bool srgb);

// Peak signal-to-noise ratio over the RGB channels in dB; +infinity for identical images.
[[nodiscard]] double psnr(const Image& a, const Image& b);
// Largest absolute difference of any RGB channel of any pixel (0..255).
[[nodiscard]] int max_channel_difference(const Image& a, const Image& b);
// Rec. 709 luma of a pixel, 0..1, on the stored (sRGB-encoded) values.
[[nodiscard]] double luma(const Image& image, int x, int y);

}  // namespace atrium::assets
