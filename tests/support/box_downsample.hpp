// Shrinking a large render to compare it with a small one: each factor x factor
// block of pixels averaged into one.
#pragma once

#include <cmath>
#include <cstdint>

#include "assets/image.hpp"

namespace atrium::testing {

inline float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
inline float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

// `image` shrunk by `factor` per axis. With `linear_light` the colour channels
// (sRGB-encoded) are averaged in linear light, as a supersampled picture is
// resolved; otherwise every channel is averaged as stored. Alpha is linear.
inline assets::Image box_downsample(const assets::Image& image, int factor, bool linear_light) {
  assets::Image small{image.width / factor, image.height / factor, {}};
  small.rgba.resize(static_cast<std::size_t>(small.width) * small.height * 4);
  const int count = factor * factor;
  for (int y = 0; y < small.height; ++y) {
    for (int x = 0; x < small.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        std::uint64_t stored = 0;
        float linear = 0.0f;
        for (int dy = 0; dy < factor; ++dy) {
          for (int dx = 0; dx < factor; ++dx) {
            const std::uint8_t value = image.pixel(x * factor + dx, y * factor + dy)[c];
            stored += value;
            linear += srgb_to_linear(value / 255.0f);
          }
        }
        const bool in_linear_light = linear_light && c < 3;
        small.rgba[(static_cast<std::size_t>(y) * small.width + x) * 4 + c] =
            in_linear_light ? static_cast<std::uint8_t>(std::lround(255.0f * linear_to_srgb(linear / static_cast<float>(count))))
                            : static_cast<std::uint8_t>((stored + count / 2) / count);
      }
    }
  }
  return small;
}

}  // namespace atrium::testing
