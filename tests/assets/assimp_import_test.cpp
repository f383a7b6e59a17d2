// OBJ and FBX files written by other tools (tests/data/model-tools, made by its
// make_fixtures.sh with assimp's and Blender's exporters from glTF files in
// ../shared/testdata): each imports with its glTF source's triangles and, once
// its units and axes are read, its source's bounds. Texture paths as exporters
// write them are found with a warning; material conventions map as documented
// (docs/real-scenes.md); bad files fail in one line naming the file.
// Renders are compared with their glTF sources in tests/render/model_render_test.cpp.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "assets/assimp_import.hpp"
#include "assets/gltf_import.hpp"
#include "assets/image.hpp"
#include "assets/model_import.hpp"
#include "assets/mtl_check.hpp"
#include "support/model_triangles.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";
const fs::path kTestdata = fs::path(ATRIUM_TESTDATA_DIR);

using testing::drawn_triangles;

// A model and its glTF source: the same triangles, the same box within `tolerance`
// of its size.
void expect_same_model(const fs::path& file, const fs::path& source, float tolerance = 1e-3f) {
  AssetManager assets;
  const ModelImport model = import_model(file, assets);
  const ModelImport reference = import_gltf(source, assets);
  EXPECT_EQ(drawn_triangles(assets, model), drawn_triangles(assets, reference)) << file.filename();
  const float size = glm::length(reference.bounds.max - reference.bounds.min);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(model.bounds.min[axis], reference.bounds.min[axis], tolerance * size) << file.filename() << " axis " << axis;
    EXPECT_NEAR(model.bounds.max[axis], reference.bounds.max[axis], tolerance * size) << file.filename() << " axis " << axis;
  }
}

TEST(AssimpImport, ObjFromAssimpIsItsSource) {
  expect_same_model(kFixtures / "torusknot.assimp.obj", kTestdata / "gltf/blender-exports/torusknot.gltf");
}

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

// A folder per test holding the cube's OBJ, with its MTL written by the test.
class ObjFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("atrium_obj_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
    fs::copy_file(kFixtures / "cube.assimp.obj", folder_ / "cube.assimp.obj");
  }
  void TearDown() override { fs::remove_all(folder_); }

  void write_mtl(const std::string& body) const {
    std::ofstream(folder_ / "cube.assimp.mtl") << "newmtl Cube\nKd 1 1 1\n" << body << "\nnewmtl $Material_1\nKd 1 1 1\n";
  }
  // The texture `name` (from tinygltf's Cube) at `relative` under the folder.
  void put(const std::string& name, const fs::path& relative) const {
    fs::create_directories((folder_ / relative).parent_path());
    fs::copy_file(kTestdata / "gltf/tinygltf/Cube" / name, folder_ / relative);
  }
  ModelImport load(AssetManager& assets, std::optional<MaterialConvention> convention = std::nullopt) const {
    ImportOptions options;
    options.convention = convention;
    return import_model(folder_ / "cube.assimp.obj", assets, options);
  }
  static const Material& cube_material(const AssetManager& assets, const ModelImport& model) {
    for (const Material& m : assets.mesh_asset(model.asset).materials) {
      if (m.name == "Cube") return m;
    }
    throw std::runtime_error("no Cube material");
  }
  std::string warnings(const ModelImport& model) const {
    std::string all;
    for (const std::string& w : model.warnings) all += w + "\n";
    return all;
  }

  fs::path folder_;
};

TEST_F(ObjFolder, TheAssimpCubeFindsItsTextureBesideIt) {
  fs::copy_file(kFixtures / "cube.assimp.mtl", folder_ / "cube.assimp.mtl");
  put("Cube_BaseColor.png", "Cube_BaseColor.png");
  AssetManager assets;
  const ModelImport model = load(assets);
  EXPECT_EQ(model.images, 1u);
  EXPECT_TRUE(model.warnings.empty()) << warnings(model);
  EXPECT_TRUE(cube_material(assets, model).base_color_texture.valid());
}

TEST_F(ObjFolder, TexturePathsAsExportersWriteThemAreFoundWithAWarning) {
  const std::pair<std::string, std::string> cases[] = {
      {"textures\\Cube_BaseColor.png", "has Windows separators"},
      {"textures/CUBE_basecolor.PNG", "differs in letter case"},
      {"C:\\Users\\artist\\sponza\\textures\\Cube_BaseColor.png", "absolute path from another machine"},
      {"elsewhere/Cube_BaseColor.png", "is not where the path says"},
  };
  for (const auto& [written, how] : cases) {
    fs::remove_all(folder_ / "textures");
    put("Cube_BaseColor.png", "textures/Cube_BaseColor.png");
    write_mtl("map_Kd " + written);
    AssetManager assets;
    const ModelImport model = load(assets);
    EXPECT_EQ(model.images, 1u) << written;
    EXPECT_TRUE(cube_material(assets, model).base_color_texture.valid()) << written;
    ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
    EXPECT_NE(model.warnings[0].find(how), std::string::npos) << model.warnings[0];
    EXPECT_NE(model.warnings[0].find("textures/Cube_BaseColor.png is used"), std::string::npos) << model.warnings[0];
  }
}

TEST_F(ObjFolder, AMissingTextureIsOneWarningAndTheNeutralDefault) {
  write_mtl("map_Kd nowhere.png");
  AssetManager assets;
  const ModelImport model = load(assets);
  ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
  EXPECT_NE(model.warnings[0].find("nowhere.png"), std::string::npos) << model.warnings[0];
  EXPECT_NE(model.warnings[0].find("cube.assimp.obj"), std::string::npos) << model.warnings[0];
  EXPECT_FALSE(cube_material(assets, model).base_color_texture.valid());
}

// Material libraries go through Atrium's file access (assimp_file_access.hpp):
// missing, a directory, another letter case, beyond the load budget.
TEST_F(ObjFolder, AMissingMaterialLibraryIsOneWarningNamingIt) {
  AssetManager assets;
  const ModelImport model = load(assets);
  ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
  EXPECT_EQ(model.warnings[0], (folder_ / "cube.assimp.obj").string() +
                                   ": 'cube.assimp.mtl', which it names, cannot be read (no such file); what it holds is left out");
  EXPECT_EQ(drawn_triangles(assets, model), 12u) << "the geometry still loads";
}

TEST_F(ObjFolder, AMaterialLibraryThatIsADirectoryIsAWarning) {
  fs::create_directory(folder_ / "cube.assimp.mtl");
  AssetManager assets;
  const ModelImport model = load(assets);
  ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
  EXPECT_NE(model.warnings[0].find("'cube.assimp.mtl', which it names, cannot be read (a directory)"), std::string::npos) << model.warnings[0];
}

TEST_F(ObjFolder, AMaterialLibraryInAnotherLetterCaseIsFoundWithAWarning) {
  fs::copy_file(kFixtures / "cube.assimp.mtl", folder_ / "CUBE.Assimp.MTL");
  put("Cube_BaseColor.png", "Cube_BaseColor.png");
  AssetManager assets;
  const ModelImport model = load(assets);
  ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
  EXPECT_NE(model.warnings[0].find("'cube.assimp.mtl' differs in letter case from the file on disk; CUBE.Assimp.MTL is used"), std::string::npos)
      << model.warnings[0];
  EXPECT_TRUE(cube_material(assets, model).base_color_texture.valid()) << "its materials are read";
}

TEST_F(ObjFolder, AMaterialLibraryBeyondTheLoadBudgetIsAWarning) {
  write_mtl(std::string(256 * 1024, '#'));
  AssetManager assets;
  ImportOptions options;
  options.memory_limit = 128 * 1024;
  const ModelImport model = import_model(folder_ / "cube.assimp.obj", assets, options);
  ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
  EXPECT_NE(model.warnings[0].find("'cube.assimp.mtl', which it names, cannot be read (256.0 KiB, more than the memory available, 128.0 KiB)"),
            std::string::npos)
      << model.warnings[0];
}

// Debian's libassimp 5.2.5 writes through a missing material on a texture
// before any newmtl (the model fuzzer's find, kept in
// tests/fuzz/regressions/model/): the library never reaches it.
TEST_F(ObjFolder, AMaterialLibraryGivingATextureBeforeAnyMaterialIsAWarning) {
  for (const std::string& statement : {"map_Kd Cube_BaseColor.png", "\tBUMP -bm 2 bumps.png", "norm n.png", "disp d.png"}) {
    std::ofstream(folder_ / "cube.assimp.mtl") << "# exported\r\n\r\n" << statement << "\r\nnewmtl Cube\r\nKd 1 1 1\r\n";
    AssetManager assets;
    const ModelImport model = load(assets);
    ASSERT_EQ(model.warnings.size(), 1u) << warnings(model);
    const std::string keyword = statement.substr(statement.find_first_not_of('\t'), statement.find(' ') - statement.find_first_not_of('\t'));
    EXPECT_NE(model.warnings[0].find("'cube.assimp.mtl', which it names, cannot be read (its line 3 gives a texture ('" + keyword +
                                     "') before any 'newmtl' names a material to give it to)"),
              std::string::npos)
        << model.warnings[0];
    EXPECT_EQ(drawn_triangles(assets, model), 12u) << "the geometry still loads";
  }
  // After a newmtl, the same statement is the material's texture.
  put("Cube_BaseColor.png", "Cube_BaseColor.png");
  write_mtl("map_Kd Cube_BaseColor.png");
  AssetManager assets;
  const ModelImport model = load(assets);
  EXPECT_TRUE(model.warnings.empty()) << warnings(model);
  EXPECT_TRUE(cube_material(assets, model).base_color_texture.valid());
}

// Where libassimp's reader ends a line: NUL and form feed too (the fuzzer's
// second find hid a texture statement after a NUL).
TEST(MtlCheck, FindsTheTextureBeforeAnyMaterialOnEveryKindOfLine) {
  const auto problem = [](std::string_view text) {
    return mtl_texture_before_material_problem(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  };
  EXPECT_EQ(problem(std::string_view("mtllib 082\0norm5", 16)), "its line 2 gives a texture ('norm5') before any 'newmtl' names a material to give it to");
  EXPECT_EQ(problem("Kd 1 1 1\fmap_Ks s.png"), "its line 2 gives a texture ('map_Ks') before any 'newmtl' names a material to give it to");
  EXPECT_EQ(problem("# a\r\n\r\n  Map_Kd a.png\n"), "its line 3 gives a texture ('Map_Kd') before any 'newmtl' names a material to give it to");
  EXPECT_EQ(problem("newmtl a\nmap_Kd a.png\n"), "");
  EXPECT_EQ(problem("Kd 1 1 1\nNs 10\n"), "") << "no texture at all";
  EXPECT_EQ(problem(""), "");
}

TEST_F(ObjFolder, PhongMaterialsBecomeRoughnessAndAlphaMasks) {
  // An exponent of 98 is GGX roughness sqrt(2 / 100); map_d becomes the colour
  // texture's alpha; a greyscale bump map is a height map, not drawn.
  put("Cube_BaseColor.png", "Cube_BaseColor.png");
  put("Cube_MetallicRoughness.png", "opacity.png");
  write_mtl("Ns 98\nmap_Kd Cube_BaseColor.png\nmap_d opacity.png\nmap_bump height.png");
  Image height{4, 4, std::vector<std::uint8_t>(64, 255)};
  for (std::size_t i = 0; i < 64; i += 4) height.rgba[i] = height.rgba[i + 1] = height.rgba[i + 2] = static_cast<std::uint8_t>(i * 4);
  write_png(folder_ / "height.png", height);
  AssetManager assets;
  const ModelImport model = load(assets);
  const Material& m = cube_material(assets, model);
  EXPECT_NEAR(m.roughness_factor, std::sqrt(0.02f), 1e-5f);
  EXPECT_EQ(m.metallic_factor, 0.0f);
  EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
  ASSERT_TRUE(m.base_color_texture.valid());
  const Image& merged = assets.texture(m.base_color_texture.texture).image;
  const Image colour = read_png(folder_ / "Cube_BaseColor.png"), opacity = read_png(folder_ / "opacity.png");
  ASSERT_EQ(merged.rgba.size(), colour.rgba.size());
  for (std::size_t i = 0; i < merged.rgba.size(); i += 4 * 101) {
    EXPECT_EQ(merged.rgba[i], colour.rgba[i]);
    EXPECT_EQ(merged.rgba[i + 3], opacity.rgba[i]) << "alpha is the opacity map's red";
  }
  EXPECT_FALSE(m.normal_texture.valid());
  bool height_warning = false;
  for (const std::string& w : model.warnings) height_warning |= w.find("height map") != std::string::npos;
  EXPECT_TRUE(height_warning) << warnings(model);
}

TEST_F(ObjFolder, BistroMaterialsReadSpecularAsOcclusionRoughnessMetalness) {
  put("Cube_BaseColor.png", "BaseColor.png");
  put("Cube_MetallicRoughness.png", "Specular.png");
  put("Cube_BaseColor.png", "Normal.png");
  write_mtl("map_Kd BaseColor.png\nmap_Ks Specular.png\nmap_bump Normal.png");
  AssetManager assets;
  const ModelImport model = load(assets, MaterialConvention::Bistro);
  EXPECT_TRUE(model.warnings.empty()) << warnings(model);
  const Material& m = cube_material(assets, model);
  ASSERT_TRUE(m.metallic_roughness_texture.valid());
  EXPECT_EQ(m.occlusion_texture.texture, m.metallic_roughness_texture.texture);
  EXPECT_EQ(m.metallic_factor, 1.0f);
  EXPECT_EQ(m.roughness_factor, 1.0f);
  EXPECT_TRUE(m.normal_texture.valid());
  EXPECT_TRUE(m.normal_green_down) << "Bistro's normal maps are DirectX's";
  EXPECT_EQ(assets.texture(m.metallic_roughness_texture.texture).color_space, ColorSpace::Linear);

  // Without its Specular texture a Bistro material is a dielectric.
  write_mtl("map_Kd BaseColor.png");
  AssetManager plain_assets;
  const Material& plain = cube_material(plain_assets, load(plain_assets, MaterialConvention::Bistro));
  EXPECT_EQ(plain.metallic_factor, 0.0f);
  EXPECT_FALSE(plain.metallic_roughness_texture.valid());
}

TEST(AssimpImport, BadFilesFailInOneLineNamingTheFile) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bad_models_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "garbage.fbx") << "this is not an FBX file at all\n";
  std::ofstream(folder / "truncated.fbx", std::ios::binary) << std::ifstream(kFixtures / "torusknot.blender-yup.fbx", std::ios::binary).rdbuf();
  fs::resize_file(folder / "truncated.fbx", 5000);
  std::ofstream(folder / "faces.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 9\n";
  for (const fs::path& file : {folder / "missing.obj", folder / "garbage.fbx", folder / "truncated.fbx", folder / "faces.obj"}) {
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

TEST(AssimpImport, UnusableTrianglesAreSkippedWithOneWarningPerReason) {
  const fs::path file = fs::temp_directory_path() / ("atrium_unusable_" + std::to_string(::getpid()) + ".obj");
  // One good triangle, one with a NaN corner, two of zero area.
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 2 0 0\n"
                         "f 1 2 3\nf 1 2 4\nf 1 2 5\nf 1 1 3\n";
  AssetManager assets;
  const ModelImport model = import_model(file, assets);
  fs::remove(file);
  EXPECT_EQ(drawn_triangles(assets, model), 1u);
  std::string all;
  for (const std::string& w : model.warnings) all += w + "\n";
  EXPECT_NE(all.find("1 of 4 triangles have a NaN or infinite corner"), std::string::npos) << all;
  EXPECT_NE(all.find("2 of 4 triangles have zero area"), std::string::npos) << all;
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
