#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include "assets/image.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {

const std::filesystem::path kFixtures = std::filesystem::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";

std::vector<std::uint8_t> read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Image decoded_image(const std::string& name) {
  const DecodedTexture decoded = decode_texture(read(kFixtures / name), ColorSpace::Srgb, std::size_t{1} << 30);
  EXPECT_TRUE(decoded.texture && !decoded.texture->compressed) << name << ": " << decoded.error;
  return decoded.texture ? decoded.texture->image : Image{};
}

// ImageMagick's 8-bit PGM and PPM (make_fixtures.sh) decode to the picture of
// its PNGs of the same image, grey as opaque grey RGBA.
TEST(TextureDecode, PgmAndPpmDecodeToThePictureOfTheirPngTwins) {
  for (const auto& [pnm, png] : {std::pair{"bricks.grey8.pgm", "bricks.grey8.png"}, std::pair{"bricks.rgb8.ppm", "bricks.rgb8.png"}}) {
    const Image from_pnm = decoded_image(pnm), from_png = decoded_image(png);
    ASSERT_EQ(from_pnm.width, 16) << pnm;
    ASSERT_EQ(from_pnm.height, 16) << pnm;
    EXPECT_EQ(max_channel_difference(from_pnm, from_png), 0) << pnm << " against " << png;
  }
  const Image grey = decoded_image("bricks.grey8.pgm");
  bool varied = false;
  for (std::size_t i = 0; i < grey.rgba.size(); i += 4) {
    EXPECT_EQ(grey.rgba[i], grey.rgba[i + 1]);
    EXPECT_EQ(grey.rgba[i], grey.rgba[i + 2]);
    EXPECT_EQ(grey.rgba[i + 3], 255);
    varied = varied || grey.rgba[i] != grey.rgba[0];
  }
  EXPECT_TRUE(varied) << "a picture, not a flat fill";
}

// Their 16-bit files are refused in one line: stb_image misread them (the
// wrong byte order) and read past its buffer.
TEST(TextureDecode, SixteenBitPgmAndPpmAreRefusedNotMisread) {
  for (const char* name : {"bricks.grey16.pgm", "bricks.rgb16.ppm"}) {
    const DecodedTexture decoded = decode_texture(read(kFixtures / name), ColorSpace::Srgb, std::size_t{1} << 30);
    EXPECT_FALSE(decoded.texture) << name;
    EXPECT_EQ(decoded.error, "16-bit PGM and PPM images are not read, as stb_image misreads them: save it with 8 bits a sample or as PNG") << name;
  }
}

}  // namespace
}  // namespace atrium::assets
