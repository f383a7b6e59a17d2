#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "assets/image.hpp"

namespace atrium::assets {
namespace {

Image filled(int w, int h, std::uint8_t value) {
  return Image{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, value)};
}

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnrAndNoDifference) {
  const Image a = filled(8, 4, 100);
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  EXPECT_EQ(max_channel_difference(a, a), 0);
}

TEST(ImageMetrics, PsnrMatchesTheDefinition) {
  const Image a = filled(8, 4, 100);
  Image b = a;
  b.rgba[0] = 110;  // one channel of one pixel off by 10
  const double mse = 100.0 / (8 * 4 * 3);
  EXPECT_NEAR(psnr(a, b), 10.0 * std::log10(255.0 * 255.0 / mse), 1e-9);
  EXPECT_EQ(max_channel_difference(a, b), 10);
}

TEST(ImageMetrics, DifferentSizesAreRefused) {
  EXPECT_THROW((void)psnr(filled(2, 2, 0), filled(2, 3, 0)), ImageError);
}

// A 1-pixel black and white checkerboard, opaque.
Image checkerboard(int w, int h) {
  Image image = filled(w, h, 255);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if ((x + y) % 2 == 0) continue;
      std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      p[0] = p[1] = p[2] = 0;
    }
  }
  return image;
}

TEST(ImageDownscale, KeepsTheAspectRatioAndAveragesInLinearLightForSrgb) {
  const Image big = checkerboard(4096, 1024);
  for (const bool srgb : {true, false}) {
    const Image small = downscale_to_fit(big, 1024, srgb);
    ASSERT_EQ(small.width, 1024);
    ASSERT_EQ(small.height, 256);
    // Half the light: 0.5 linear is 188 in sRGB, 128 where the values are linear.
    const int expected = srgb ? static_cast<int>(std::lround(255.0 * (1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055))) : 128;
    // The outermost pixels' filters reach past the edge, where the border is
    // repeated (one colour of the pattern), so they are left out.
    int worst = 0;
    for (int y = 1; y + 1 < small.height; ++y) {
      for (int x = 1; x + 1 < small.width; ++x) {
        const std::uint8_t* p = small.pixel(x, y);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p[c] - expected));
        ASSERT_EQ(p[3], 255) << "alpha stays opaque";
      }
    }
    EXPECT_LE(worst, 1) << (srgb ? "sRGB" : "linear");
  }
}

TEST(ImageDownscale, AnImageThatFitsComesBackAsItIs) {
  const Image image = checkerboard(64, 32);
  const Image same = downscale_to_fit(image, 64, true);
  EXPECT_EQ(same.width, 64);
  EXPECT_EQ(same.rgba, image.rgba);
  const Image tall = downscale_to_fit(checkerboard(3, 5000), 1000, false);
  EXPECT_EQ(tall.width, 1);
  EXPECT_EQ(tall.height, 1000);
}

TEST(ImagePng, RoundTripsThroughAFile) {
  Image a = filled(5, 3, 0);
  for (std::size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = static_cast<std::uint8_t>(i * 7);
  const auto path = std::filesystem::temp_directory_path() / "atrium_image_test.png";
  write_png(path, a);
  const Image b = read_png(path);
  EXPECT_EQ(b.width, 5);
  EXPECT_EQ(b.height, 3);
  EXPECT_EQ(b.rgba, a.rgba);
  std::filesystem::remove(path);
}

TEST(ImagePng, UnwritablePathNamesTheFile) {
  try {
    write_png("/nonexistent-folder/x.png", filled(1, 1, 0));
    FAIL() << "expected ImageError";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace atrium::assets
