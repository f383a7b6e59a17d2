#include "assets/image.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <stb_image.h>
#include <stb_image_resize.h>
#include <stb_image_write.h>

namespace atrium::assets {
namespace {
void require_same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) {
    throw ImageError("cannot compare a " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                     " image with a " + std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
  }
}
}  // namespace

void write_png(const std::filesystem::path& path, const Image& image) {
  if (!stbi_write_png(path.string().c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
    throw ImageError(path.string() + ": cannot write the PNG (does the folder exist and is it writable?)");
  }
}

Image read_png(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  stbi_uc* data = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
  if (!data) throw ImageError(path.string() + ": cannot read the image: " + stbi_failure_reason());
  Image image{width, height, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(width) * height * 4)};
  stbi_image_free(data);
  return image;
}

Image downscale_to_fit(const Image& image, int max_size, bool srgb) {
  if (image.width <= max_size && image.height <= max_size) return image;
  const double scale = static_cast<double>(max_size) / std::max(image.width, image.height);
  Image out;
  out.width = std::clamp(static_cast<int>(std::lround(image.width * scale)), 1, max_size);
  out.height = std::clamp(static_cast<int>(std::lround(image.height * scale)), 1, max_size);
  out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  constexpr int kAlpha = 3;
  const int ok = srgb ? stbir_resize_uint8_srgb(image.rgba.data(), image.width, image.height, 0, out.rgba.data(), out.width,
                                                out.height, 0, 4, kAlpha, 0)
                      : stbir_resize_uint8(image.rgba.data(), image.width, image.height, 0, out.rgba.data(), out.width, out.height, 0, 4);
  if (!ok) throw ImageError("cannot downscale a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
  return out;
}

double psnr(const Image& a, const Image& b) {
  require_same_size(a, b);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double d = static_cast<double>(a.rgba[i + c]) - static_cast<double>(b.rgba[i + c]);
      sum += d * d;
      ++count;
    }
  }
  if (sum == 0.0) return std::numeric_limits<double>::infinity();
  const double mse = sum / static_cast<double>(count);
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

int max_channel_difference(const Image& a, const Image& b) {
  require_same_size(a, b);
  int largest = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(static_cast<int>(a.rgba[i + c]) - static_cast<int>(b.rgba[i + c])));
    }
  }
  return largest;
}

double luma(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

}  // namespace atrium::assets
