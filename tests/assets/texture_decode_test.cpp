#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <gtest/gtest.h>

#include "assets/image.hpp"
#include "assets/image_decoders.hpp"
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

// stb_image's picture of a file: the reader PNG and JPEG had before libspng
// and TurboJPEG (natively), and the page's still.
Image stb_image(const std::string& name) {
  std::string error;
  std::optional<Image> image = decode_with_stb(read(kFixtures / name), std::size_t{1} << 30, error);
  EXPECT_TRUE(image) << name << ": " << error;
  return image ? std::move(*image) : Image{};
}

// ImageMagick's PNGs in every layout the readers must expand (16-bit RGBA,
// palette with transparency, grey with alpha, Adam7 interlacing) decode to
// the pixels stb_image gave, and a gAMA chunk of 1.0 changes nothing: glTF
// has colour-space chunks ignored.
TEST(TextureDecode, PngInEveryLayoutDecodesToStbImagesPixels) {
  for (const char* name : {"bricks.32.png", "leaves.rgba16.png", "leaves.palette.png", "leaves.grey-alpha.png", "bricks.interlaced.png",
                           "bricks.gamma1.png"}) {
    const Image decoded = decoded_image(name), reference = stb_image(name);
    ASSERT_EQ(decoded.width, 32) << name;
    ASSERT_EQ(decoded.height, 32) << name;
    EXPECT_EQ(max_channel_difference(decoded, reference), 0) << name;
  }
  EXPECT_EQ(max_channel_difference(decoded_image("bricks.gamma1.png"), decoded_image("bricks.32.png")), 0);
  EXPECT_EQ(max_channel_difference(decoded_image("bricks.interlaced.png"), decoded_image("bricks.32.png")), 0);
  const Image palette = decoded_image("leaves.palette.png");
  int transparent = 0, opaque = 0;
  for (std::size_t i = 3; i < palette.rgba.size(); i += 4) {
    transparent += palette.rgba[i] == 0;
    opaque += palette.rgba[i] == 255;
  }
  EXPECT_GT(transparent, 0) << "the palette's tRNS entries become alpha";
  EXPECT_GT(opaque, 0);
}

// ImageMagick's JPEGs (baseline 4:2:0, progressive, grey, Adobe CMYK) decode
// to the picture they were made from, and to within a few levels of
// stb_image's decode (IDCT and chroma upsampling differ by rounding).
TEST(TextureDecode, JpegInEveryLayoutDecodesToItsSourcePicture) {
  const Image source = decoded_image("bricks.32.png");
  for (const char* name : {"bricks.baseline.jpg", "bricks.progressive.jpg", "bricks.grey.jpg", "bricks.cmyk.jpg"}) {
    const Image decoded = decoded_image(name), reference = stb_image(name);
    ASSERT_EQ(decoded.width, 32) << name;
    ASSERT_EQ(decoded.height, 32) << name;
    EXPECT_GT(psnr(decoded, reference), 40.0) << name << " against stb_image's decode";
    if (std::string(name) != "bricks.grey.jpg") EXPECT_GT(psnr(decoded, source), 30.0) << name << " against bricks.32.png";
    for (std::size_t i = 3; i < decoded.rgba.size(); i += 4) ASSERT_EQ(decoded.rgba[i], 255) << name;
  }
  const Image grey = decoded_image("bricks.grey.jpg");
  for (std::size_t i = 0; i < grey.rgba.size(); i += 4) {
    ASSERT_EQ(grey.rgba[i], grey.rgba[i + 1]);
    ASSERT_EQ(grey.rgba[i], grey.rgba[i + 2]);
  }
}

// A size the header declares beyond the memory available is refused before
// anything is decoded, with the size in the message, in both formats.
TEST(TextureDecode, PngAndJpegLargerThanTheMemoryAvailableAreRefused) {
  for (const char* name : {"bricks.32.png", "bricks.baseline.jpg"}) {
    const DecodedTexture decoded = decode_texture(read(kFixtures / name), ColorSpace::Srgb, 1000);
    EXPECT_FALSE(decoded.texture) << name;
    EXPECT_EQ(decoded.error, "32x32 needs 4.0 KiB, more than the 1000 bytes of memory available") << name;
  }
}

// ImageMagick's GIF, PSD and HDR files, which stb_image would read, are
// refused in one line that says what is read instead.
TEST(TextureDecode, GifPsdAndHdrAreRefusedNamingTheFormatsRead) {
  for (const auto& [name, format] : {std::pair{"bricks.8.gif", "GIF"}, std::pair{"bricks.8.psd", "Photoshop (PSD)"},
                                     std::pair{"bricks.8.hdr", "Radiance HDR"}}) {
    const DecodedTexture decoded = decode_texture(read(kFixtures / name), ColorSpace::Srgb, std::size_t{1} << 30);
    EXPECT_FALSE(decoded.texture) << name;
    EXPECT_EQ(decoded.error, std::string(format) + " images are not read as textures, only PNG, JPEG, TGA, BMP, 8-bit PGM and PPM, and DDS: save it as PNG");
  }
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

// ImageMagick's TGA (colour-mapped plain and run-length encoded, true-colour
// RLE, 32-bit with alpha) and BMP (24-bit, 32-bit with an alpha mask) decode
// to the pixels of their PNG twins, alpha included.
TEST(TextureDecode, TgaAndBmpDecodeToThePictureOfTheirPngTwins) {
  for (const auto& [file, png] : {std::pair{"bricks.rgb8.tga", "bricks.rgb8.png"}, std::pair{"bricks.rle.tga", "bricks.rgb8.png"},
                                  std::pair{"bricks.truecolor-rle.tga", "bricks.rgb8.png"}, std::pair{"leaves.rgba8.tga", "leaves.rgba8.png"},
                                  std::pair{"bricks.rgb8.bmp", "bricks.rgb8.png"}, std::pair{"leaves.rgba8.bmp", "leaves.rgba8.png"}}) {
    const Image decoded = decoded_image(file), twin = decoded_image(png);
    ASSERT_EQ(decoded.width, twin.width) << file;
    ASSERT_EQ(decoded.height, twin.height) << file;
    EXPECT_EQ(decoded.rgba, twin.rgba) << file << " against " << png;
  }
  // The alpha is a picture too: the leaves' cut-outs, not one value.
  const Image leaves = decoded_image("leaves.rgba8.tga");
  bool clear = false, opaque = false;
  for (std::size_t i = 3; i < leaves.rgba.size(); i += 4) {
    clear = clear || leaves.rgba[i] == 0;
    opaque = opaque || leaves.rgba[i] == 255;
  }
  EXPECT_TRUE(clear && opaque);
}

// ImageMagick's run-length encoded BMP, which stb_image does not read (it
// said "unknown image type"), is refused in one line that says what to do.
TEST(TextureDecode, RunLengthEncodedBmpIsRefusedSayingWhy) {
  const DecodedTexture decoded = decode_texture(read(kFixtures / "bricks.rle8.bmp"), ColorSpace::Srgb, std::size_t{1} << 30);
  EXPECT_FALSE(decoded.texture);
  EXPECT_EQ(decoded.error, "run-length encoded BMP images are not read: save it uncompressed or as PNG");
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
