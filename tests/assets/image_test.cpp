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
