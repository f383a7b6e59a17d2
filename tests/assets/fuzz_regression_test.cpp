// Inputs the fuzzers once found or were seeded with (tests/fuzz/regressions):
// each must load or be refused with the loader's own error, never crash.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include <gtest/gtest.h>

#include "assets/gltf_import.hpp"
#include "assets/model_import.hpp"
#include "assets/scene_file.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {

const std::filesystem::path kRegressions = std::filesystem::path(ATRIUM_SOURCE_DIR) / "tests/fuzz/regressions";

std::vector<std::filesystem::path> inputs(const char* target) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions / target)) {
    if (entry.is_regular_file() && entry.path().filename() != ".gitkeep") files.push_back(entry.path());
  }
  return files;
}

TEST(FuzzRegressions, SceneFilesLoadOrAreRefused) {
  for (const auto& file : inputs("scene_file")) {
    AssetManager assets;
    LoadReport report;
    try {
      (void)load_scene_file(file, assets, report);
    } catch (const SceneFileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << "the error names the file: " << e.what();
    } catch (const ImportError&) {
    }
  }
}

TEST(FuzzRegressions, GltfFilesImportOrAreRefused) {
  for (const auto& file : inputs("gltf")) {
    AssetManager assets;
    try {
      (void)import_gltf(file, assets);
    } catch (const ImportError& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << "the error names the file: " << e.what();
    }
  }
}

// Hostile OBJ, MTL and FBX files (made from real tools' files by
// regressions/model/make_hostile.py), imported beside a directory named like a
// material library: each imports with warnings or is refused in one line.
TEST(FuzzRegressions, ModelFilesImportOrAreRefused) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("atrium_model_regressions_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder / "folder.mtl");
  std::size_t imported = 0, refused = 0;
  for (const auto& file : inputs("model")) std::filesystem::copy_file(file, folder / file.filename());
  for (const auto& file : inputs("model")) {
    if (!is_model_file(file)) continue;
    AssetManager assets;
    try {
      const ModelImport model = import_model(folder / file.filename(), assets);
      for (const std::string& warning : model.warnings) EXPECT_EQ(warning.find('\n'), std::string::npos) << warning;
      ++imported;
    } catch (const ImportError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind((folder / file.filename()).string() + ": ", 0), 0u) << "the error names the file: " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      ++refused;
    }
  }
  std::filesystem::remove_all(folder);
  // OBJ imports in both builds (tinyobjloader); the browser build refuses FBX,
  // naming the file.
  EXPECT_GE(imported, 3u);
  EXPECT_GE(refused, 5u);
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzRegressions, TexturesDecodeOrAreRefused) {
  for (const auto& file : inputs("texture")) {
    const DecodedTexture decoded = decode_texture(read_bytes(file), ColorSpace::Srgb, std::size_t{1} << 30);
    EXPECT_NE(decoded.texture.has_value(), !decoded.error.empty()) << file << ": a texture or an error, not both";
  }
}

// A PGM whose width has more digits than an int holds: refused before
// stb_image parses it into an int that overflows.
TEST(FuzzRegressions, APnmHeaderNumberBeyondAnIntIsRefusedUpFront) {
  const DecodedTexture decoded =
      decode_texture(read_bytes(kRegressions / "texture/pnm-header-number-overflows-stb-int.pgm"), ColorSpace::Srgb, std::size_t{1} << 30);
  EXPECT_FALSE(decoded.texture);
  EXPECT_EQ(decoded.error, "a PGM or PPM header number beyond 2147483647");
}

// A JPEG behind twelve 0xff fill bytes: stb_image's JPEG reader (whose
// Huffman tables overflow) takes it for one, so it goes to TurboJPEG, which
// refuses it in one line.
TEST(FuzzRegressions, AJpegAfterFillBytesNeverReachesStbImage) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the page reads JPEG with stb_image";
#endif
  const DecodedTexture decoded =
      decode_texture(read_bytes(kRegressions / "texture/jpeg-after-fill-bytes-reaches-stb.jpg"), ColorSpace::Srgb, std::size_t{1} << 30);
  EXPECT_FALSE(decoded.texture);
  EXPECT_EQ(decoded.error.rfind("not a readable JPEG: ", 0), 0u) << decoded.error;
}

// A 33 KB PNG whose second IDAT chunk claims 1 GB: refused before stb_image
// grows its buffer for it; the PNGs other tools wrote still decode.
TEST(FuzzRegressions, APngChunkLongerThanTheFileIsRefusedUpFront) {
  const DecodedTexture decoded =
      decode_texture(read_bytes(kRegressions / "texture/png-chunk-length-beyond-file.png"), ColorSpace::Srgb, std::size_t{1} << 30);
  EXPECT_FALSE(decoded.texture);
  EXPECT_EQ(decoded.error, "PNG chunk 'IDAT' claims 1090519753 bytes but the file holds 823 more");
  int decoded_pngs = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::filesystem::path(ATRIUM_SOURCE_DIR) / "tests/data")) {
    if (entry.path().extension() != ".png") continue;
    const DecodedTexture png = decode_texture(read_bytes(entry.path()), ColorSpace::Srgb, std::size_t{1} << 30);
    EXPECT_TRUE(png.texture) << entry.path() << ": " << png.error;
    ++decoded_pngs;
  }
  EXPECT_GT(decoded_pngs, 0);
}

}  // namespace
}  // namespace atrium::assets
