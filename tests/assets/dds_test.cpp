// DDS textures (dds.hpp) as ImageMagick writes them (tests/data/model-tools,
// made by make_fixtures.sh from two Sponza textures, with PNG twins): each reads
// with its format, size and mip chain, and decodes to its twin's pixels, exactly
// when uncompressed and within block compression's error otherwise. Broken and
// unsupported files give one phrase, never a crash. BC4, BC5 and BC7 have no
// packaged encoder here: their blocks are built from the formats' definitions.
#include <algorithm>
#include <filesystem>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "assets/dds.hpp"
#include "assets/image.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";

std::vector<std::uint8_t> read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Image png(const char* name) { return read_png(kFixtures / name); }

DdsTexture dds(const char* name) {
  std::string error;
  const std::optional<DdsTexture> texture = read_dds(read(kFixtures / name), error);
  EXPECT_TRUE(texture) << name << ": " << error;
  return texture.value_or(DdsTexture{});
}

TEST(Dds, Bc1WithItsMipChainDecodesCloseToItsTwin) {
  const DdsTexture texture = dds("bricks.bc1.dds");
  ASSERT_TRUE(texture.compressed);
  EXPECT_EQ(texture.compressed->format, BlockFormat::BC1);
  EXPECT_EQ(texture.compressed->width, 128);
  EXPECT_EQ(texture.compressed->levels.size(), 8u) << "128 down to 1";
  EXPECT_EQ(texture.compressed->levels[0].size(), 32u * 32u * 8u);
  EXPECT_EQ(texture.compressed->levels[7].size(), 8u);
  std::string error;
  const std::optional<Image> decoded = decode_blocks(*texture.compressed, error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_GE(psnr(*decoded, png("bricks.png")), 30.0);
}

TEST(Dds, Bc3KeepsItsAlpha) {
  const DdsTexture texture = dds("leaves.bc3.dds");
  ASSERT_TRUE(texture.compressed);
  EXPECT_EQ(texture.compressed->format, BlockFormat::BC3);
  std::string error;
  const std::optional<Image> decoded = decode_blocks(*texture.compressed, error);
  ASSERT_TRUE(decoded) << error;
  const Image twin = png("leaves.png");
  double alpha_error = 0;
  int transparent = 0;
  for (std::size_t i = 3; i < twin.rgba.size(); i += 4) {
    alpha_error += std::abs(static_cast<int>(decoded->rgba[i]) - static_cast<int>(twin.rgba[i]));
    transparent += twin.rgba[i] < 128;
  }
  EXPECT_GT(transparent, 1000) << "the leaves have holes";
  EXPECT_LT(alpha_error / (twin.rgba.size() / 4), 4.0) << "mean alpha error, 0..255";
}

TEST(Dds, UncompressedRgbAndRgbaAreTheirTwinsExactly) {
  for (const auto& [file, twin] : {std::pair{"bricks.rgba.dds", "bricks.png"}, std::pair{"leaves.rgba.dds", "leaves.png"}}) {
    const DdsTexture texture = dds(file);
    EXPECT_FALSE(texture.compressed) << file;
    const Image expected = png(twin);
    ASSERT_EQ(texture.rgba.width, expected.width) << file;
    EXPECT_EQ(texture.rgba.rgba, expected.rgba) << file;
  }
}

TEST(Dds, DecodeTextureKeepsBlocksCompressed) {
  const DecodedTexture decoded = decode_texture(read(kFixtures / "bricks.bc1.dds"), ColorSpace::Srgb, 1u << 30);
  ASSERT_TRUE(decoded.texture) << decoded.error;
  EXPECT_TRUE(decoded.texture->compressed);
  EXPECT_EQ(decoded.texture->width(), 128);
  EXPECT_EQ(decoded.texture->bytes(), read(kFixtures / "bricks.bc1.dds").size() - 128) << "the blocks, without the header";
}

// A DX10 DDS of one 4x4 block per level, as the formats define it.
std::vector<std::uint8_t> dx10_dds(std::uint32_t dxgi, const std::vector<std::uint8_t>& block) {
  constexpr std::size_t kHeader = 4 + 124 + 20;
  std::vector<std::uint8_t> file(kHeader + block.size(), 0);
  auto put = [&](std::size_t offset, std::uint32_t value) { std::memcpy(&file[offset], &value, 4); };
  std::memcpy(file.data(), "DDS ", 4);
  put(4, 124);
  put(8, 0x1007);
  put(12, 4);
  put(16, 4);
  put(76, 32);
  put(80, 0x4);
  std::memcpy(&file[84], "DX10", 4);
  put(128, dxgi);
  put(132, 3);  // TEXTURE2D
  put(140, 1);  // one array element
  std::copy(block.begin(), block.end(), file.begin() + kHeader);
  return file;
}

TEST(Dds, Bc4Bc5AndBc7ReadFromTheirDx10Headers) {
  // BC4: both endpoints 200, every index 0: red 200 everywhere.
  std::vector<std::uint8_t> bc4{200, 200, 0, 0, 0, 0, 0, 0};
  // BC5: two BC4 blocks, red 64 and green 192.
  std::vector<std::uint8_t> bc5{64, 64, 0, 0, 0, 0, 0, 0, 192, 192, 0, 0, 0, 0, 0, 0};
  // BC7 mode 6 (bit 6 set): one subset, RGBA endpoints 7+1 bits; all zero = transparent black.
  std::vector<std::uint8_t> bc7(16, 0);
  bc7[0] = 0x40;
  for (const auto& [dxgi, block, format] : {std::tuple{80u, bc4, BlockFormat::BC4}, std::tuple{83u, bc5, BlockFormat::BC5},
                                            std::tuple{98u, bc7, BlockFormat::BC7}}) {
    std::string error;
    const std::optional<DdsTexture> texture = read_dds(dx10_dds(dxgi, block), error);
    ASSERT_TRUE(texture) << error;
    ASSERT_TRUE(texture->compressed);
    EXPECT_EQ(texture->compressed->format, format);
    EXPECT_EQ(texture->compressed->levels.at(0), block);
  }
  std::string error;
  const std::optional<DdsTexture> bc5_texture = read_dds(dx10_dds(83, bc5), error);
  const std::optional<Image> decoded = decode_blocks(*bc5_texture->compressed, error);
  ASSERT_TRUE(decoded) << error;
  EXPECT_EQ(decoded->rgba[0], 64);
  EXPECT_EQ(decoded->rgba[1], 192);
  // BC4 with endpoints 10 and 250, the first texel's 3-bit index 1 (the second
  // endpoint), the others 0: grey 250 then grey 10, as GL's RED swizzle samples it.
  const std::vector<std::uint8_t> bc4_two{10, 250, 0x01, 0, 0, 0, 0, 0};
  const std::optional<Image> grey = decode_blocks(*read_dds(dx10_dds(80, bc4_two), error)->compressed, error);
  ASSERT_TRUE(grey) << error;
  EXPECT_EQ((std::vector<int>{grey->rgba[0], grey->rgba[1], grey->rgba[2], grey->rgba[3]}), (std::vector<int>{250, 250, 250, 255}));
  EXPECT_EQ((std::vector<int>{grey->rgba[4], grey->rgba[5], grey->rgba[6]}), (std::vector<int>{10, 10, 10}));
  EXPECT_FALSE(decode_blocks(*read_dds(dx10_dds(98, bc7), error)->compressed, error)) << "BC7 is left to the driver";
  EXPECT_NE(error.find("BC7"), std::string::npos);
}

TEST(Dds, BrokenAndUnsupportedFilesSayWhy) {
  std::vector<std::uint8_t> bc1 = read(kFixtures / "bricks.bc1.dds");
  std::string error;
  EXPECT_FALSE(read_dds(std::vector<std::uint8_t>(bc1.begin(), bc1.begin() + 200), error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  std::vector<std::uint8_t> cube = bc1;
  cube[112] = 0x00;
  cube[113] = 0x02;  // DDSCAPS2_CUBEMAP
  EXPECT_FALSE(read_dds(cube, error));
  EXPECT_NE(error.find("cube map"), std::string::npos) << error;
  std::vector<std::uint8_t> huge = bc1;
  const std::uint32_t side = 1u << 30;
  std::memcpy(&huge[12], &side, 4);
  EXPECT_FALSE(read_dds(huge, error)) << "a declared size beyond the file is refused before anything is allocated";
  std::vector<std::uint8_t> unknown = bc1;
  std::memcpy(&unknown[84], "ETC2", 4);
  EXPECT_FALSE(read_dds(unknown, error));
  EXPECT_NE(error.find("'ETC2'"), std::string::npos) << error;
  EXPECT_FALSE(read_dds(dx10_dds(2, std::vector<std::uint8_t>(64)), error)) << "R32G32B32A32_FLOAT";
  EXPECT_NE(error.find("DXGI format 2"), std::string::npos) << error;
}

}  // namespace
}  // namespace atrium::assets
