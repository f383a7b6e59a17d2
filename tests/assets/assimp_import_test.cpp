// FBX files written by Blender (tests/data/model-tools, made by its
// make_fixtures.sh from glTF files in ../shared/testdata): each imports with
// its glTF source's triangles and, once its units and axes are read, its
// source's bounds; embedded textures are read; bad files fail in one line
// naming the file. The format table's routing is tested here too. OBJ is
// obj_import_test.cpp's; renders are compared with their glTF sources in
// tests/render/model_render_test.cpp.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "assets/assimp_import.hpp"
#include "assets/gltf_import.hpp"
#include "assets/model_import.hpp"
#include "support/model_triangles.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";
const fs::path kTestdata = fs::path(ATRIUM_TESTDATA_DIR);

using testing::drawn_triangles;
using testing::expect_same_model;

TEST(AssimpImport, FbxFromBlenderIsItsSourceZUpOrYUp) {
  expect_same_model(kFixtures / "torusknot.blender-yup.fbx", kTestdata / "gltf/blender-exports/torusknot.gltf");
  expect_same_model(kFixtures / "subpass_scene_opaque.blender-zup.fbx", kTestdata / "gltf/blender-exports/subpass_scene_opaque.gltf");
}

TEST(AssimpImport, TexturesAnFbxEmbedsAreReadFromIt) {
  // Blender embeds the normal map under its file name; alone in a folder,
  // the FBX still has it.
  const fs::path folder = fs::temp_directory_path() / ("atrium_fbx_embedded_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  fs::copy_file(kFixtures / "mirror-f.plain.fbx", folder / "mirror-f.plain.fbx", fs::copy_options::overwrite_existing);
  AssetManager assets;
  const ModelImport model = import_model(folder / "mirror-f.plain.fbx", assets);
  fs::remove_all(folder);
  EXPECT_EQ(model.images, 1u);
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
  EXPECT_TRUE(assets.mesh_asset(model.asset).materials.at(0).normal_texture.valid());
}

TEST(AssimpImport, BadFilesFailInOneLineNamingTheFile) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bad_models_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "garbage.fbx") << "this is not an FBX file at all\n";
  std::ofstream(folder / "truncated.fbx", std::ios::binary) << std::ifstream(kFixtures / "torusknot.blender-yup.fbx", std::ios::binary).rdbuf();
  fs::resize_file(folder / "truncated.fbx", 5000);
  for (const fs::path& file : {folder / "missing.fbx", folder / "garbage.fbx", folder / "truncated.fbx"}) {
    AssetManager assets;
    try {
      (void)import_model(file, assets);
      ADD_FAILURE() << file << " loaded";
    } catch (const ImportError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  fs::remove_all(folder);
}

TEST(ModelImport, ConventionsAndFormatsHaveOneNameEach) {
  EXPECT_EQ(material_convention("gltf"), MaterialConvention::Gltf);
  EXPECT_EQ(material_convention("bistro"), MaterialConvention::Bistro);
  EXPECT_EQ(material_convention("phong"), MaterialConvention::Phong);
  EXPECT_FALSE(material_convention("unreal"));
  for (const char* file : {"a.gltf", "a.GLB", "b.obj", "c.FBX", "d.dae", "e.3ds", "f.ply"}) EXPECT_TRUE(is_model_file(file)) << file;
  for (const char* file : {"a.json", "b.png", "c", "d.mtl"}) EXPECT_FALSE(is_model_file(file)) << file;
}

// The format table routes each extension to its importer: a file each row
// claims is read by that row's importer (the same file under each extension
// of the row fails the same way), and a file no row claims is refused naming
// every format.
TEST(ModelImport, TheFormatTableRoutesEveryExtensionAndNamesThemWhenNoneFits) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("atrium_formats_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  for (const ModelFormat& format : model_formats()) {
    for (const std::string_view extension : format.extensions) {
      const std::filesystem::path file = folder / ("empty" + std::string(extension));
      std::ofstream(file) << "";
      AssetManager assets;
      try {
        (void)import_model(file, assets);
        ADD_FAILURE() << file << " imported from an empty file";
      } catch (const ImportError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << format.name << ": " << e.what();
      }
    }
  }
  AssetManager assets;
  try {
    (void)import_model(folder / "model.blend", assets);
    ADD_FAILURE() << ".blend imported";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()), (folder / "model.blend").string() + ": not a model file Atrium reads (" + model_formats_text() + ")");
  }
  EXPECT_NE(model_formats_text().find("glTF (.gltf, .glb)"), std::string::npos);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace atrium::assets
