// docs/gltf-extensions.md and the extension table (gltf_extensions.cpp) say
// the same: one row per extension, the same support and the same words. And the
// extensions whose handling is the importer's choice between sources do choose.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "assets/gltf_extensions.hpp"
#include "assets/gltf_import.hpp"

namespace atrium::assets {
namespace {

TEST(GltfExtensions, TheDocsListEveryExtensionAsTheTableDoes) {
  std::ifstream in(std::filesystem::path(ATRIUM_SOURCE_DIR) / "docs/gltf-extensions.md");
  std::stringstream page;
  page << in.rdbuf();
  std::size_t rows = 0;
  for (std::string line; std::getline(page, line);) rows += line.rfind("| `", 0) == 0;
  EXPECT_EQ(rows, gltf_extensions().size()) << "one row per extension";
  for (const GltfExtension& e : gltf_extensions()) {
    const std::string row = "| `" + std::string(e.name) + "` | " + (e.supported ? "yes" : "no") + " | " + std::string(e.effect) + " |";
    EXPECT_NE(page.str().find(row), std::string::npos) << "missing or different: " << row;
  }
}

TEST(GltfExtensions, NamesAreUnique) {
  for (const GltfExtension& e : gltf_extensions()) EXPECT_EQ(find_gltf_extension(e.name), &e) << e.name;
  EXPECT_EQ(find_gltf_extension("EXT_not_a_thing"), nullptr);
}

TEST(GltfExtensions, MsftTextureDdsIsPreferredAndStaysCompressed) {
  // tinygltf's Cube with a DDS (ImageMagick's BC1) beside its colour PNG.
  namespace fs = std::filesystem;
  const fs::path cube = fs::path(ATRIUM_TESTDATA_DIR) / "gltf/tinygltf/Cube";
  const fs::path folder = fs::temp_directory_path() / ("atrium_msft_dds_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const char* file : {"Cube.bin", "Cube_BaseColor.png", "Cube_MetallicRoughness.png"}) fs::copy_file(cube / file, folder / file);
  fs::copy_file(fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools/bricks.bc1.dds", folder / "bricks.dds");
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(cube / "Cube.gltf"));
  gltf["images"].push_back({{"uri", "bricks.dds"}});
  gltf["textures"][0]["extensions"]["MSFT_texture_dds"]["source"] = gltf["images"].size() - 1;
  gltf["extensionsUsed"] = {"MSFT_texture_dds"};
  std::ofstream(folder / "cube.gltf") << gltf.dump();
  AssetManager assets;
  const ModelImport model = import_gltf(folder / "cube.gltf", assets);
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
  const Material& material = assets.mesh_asset(model.asset).materials.at(0);
  ASSERT_TRUE(material.base_color_texture.valid());
  const TextureData& texture = assets.texture(material.base_color_texture.texture);
  ASSERT_TRUE(texture.compressed) << "the PNG was read instead of the DDS";
  EXPECT_EQ(texture.compressed->format, BlockFormat::BC1);
  EXPECT_EQ(texture.color_space, ColorSpace::Srgb);
  EXPECT_FALSE(assets.texture(material.metallic_roughness_texture.texture).compressed) << "a texture without the extension reads its PNG";
  fs::remove_all(folder);
}

}  // namespace
}  // namespace atrium::assets
