// OBJ files with their MTL libraries, as exporters write them, through the
// importer both builds share (tinyobjloader; web.asset_tests runs this file in
// Node against the WebAssembly build): an OBJ written by assimp imports with
// its glTF source's triangles and bounds; material libraries and texture paths
// are found with a warning; material conventions map as documented
// (docs/real-scenes.md); geometry without normals is smooth across texture
// seams; bad files fail in one line naming the file and the line or face.
// Renders are compared with their glTF sources in tests/render/model_render_test.cpp.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "assets/image.hpp"
#include "assets/model_import.hpp"
#include "assets/obj_import.hpp"
#include "support/model_triangles.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";
const fs::path kTestdata = fs::path(ATRIUM_TESTDATA_DIR);

using testing::drawn_triangles;

TEST(ObjImport, ObjFromAssimpIsItsSource) {
  testing::expect_same_model(kFixtures / "torusknot.assimp.obj", kTestdata / "gltf/blender-exports/torusknot.gltf");
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

// Material libraries are found and read as textures are (file_lookup.hpp):
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

// A texture statement before any `newmtl` belongs to no material (the model
// fuzzer's find against libassimp 5.2.5, which wrote through the missing
// material; tests/fuzz/regressions/model/): the library is read and the
// statement given to none.
TEST_F(ObjFolder, ATextureBeforeAnyMaterialIsGivenToNone) {
  put("Cube_BaseColor.png", "Cube_BaseColor.png");
  for (const std::string& statement : {"map_Kd Cube_BaseColor.png", "\tBUMP -bm 2 Cube_BaseColor.png", "norm Cube_BaseColor.png"}) {
    std::ofstream(folder_ / "cube.assimp.mtl") << "# exported\r\n\r\n" << statement << "\r\nnewmtl Cube\r\nKd 1 1 1\r\n";
    AssetManager assets;
    const ModelImport model = load(assets);
    EXPECT_TRUE(model.warnings.empty()) << warnings(model);
    EXPECT_FALSE(cube_material(assets, model).base_color_texture.valid()) << statement;
    EXPECT_FALSE(cube_material(assets, model).normal_texture.valid()) << statement;
    EXPECT_EQ(drawn_triangles(assets, model), 12u) << "the geometry loads";
  }
  // After a newmtl, the same statement is the material's texture.
  write_mtl("map_Kd Cube_BaseColor.png");
  AssetManager assets;
  const ModelImport model = load(assets);
  EXPECT_TRUE(model.warnings.empty()) << warnings(model);
  EXPECT_TRUE(cube_material(assets, model).base_color_texture.valid());
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

TEST(ObjImport, UnusableTrianglesAreSkippedWithOneWarningPerReason) {
  const fs::path file = fs::temp_directory_path() / ("atrium_unusable_" + std::to_string(::getpid()) + ".obj");
  // One good triangle, one with an infinite corner (1e999: tinyobjloader
  // reads "nan" as 0), two of zero area.
  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e999 0 0\nv 2 0 0\n"
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


// An OBJ written by a test in its own folder, imported; warnings joined.
class ObjText : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("atrium_objtext_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(folder_ / name, std::ios::binary) << text;
    return folder_ / name;
  }
  // The one-line refusal of `text` as an OBJ ("" when it loads).
  std::string refusal(const std::string& text) const {
    const fs::path file = write("model.obj", text);
    AssetManager assets;
    try {
      (void)import_model(file, assets);
      return "";
    } catch (const ImportError& e) {
      return e.what();
    }
  }
  fs::path folder_;
};

TEST_F(ObjText, BadFilesFailInOneLineNamingTheFileAndWhere) {
  const std::string file = (folder_ / "model.obj").string();
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nf 1 2 9\n"), file + ": shape 0: triangle 0 names vertex 9 of 2");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -5 1 2\n"), file + ": shape 0: triangle 0 names a vertex before the first");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4\n"), file + ": shape 0: triangle 0 names normal 4 of 1");
  EXPECT_EQ(refusal("o box\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/7 2/1 3/1\n"), file + ": shape 0 'box': triangle 0 names texture coordinate 7 of 0");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 0\n"), file + ": line 5: an 'f' statement with an index of zero or not a number");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n"), file + ": line 4: an 'f' statement with an index of zero or not a number");
  EXPECT_EQ(refusal(""), file + ": it has no vertices ('v' lines)");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nl 1 2\n"), file + ": it has no faces ('f' lines) with three or more corners");
  EXPECT_EQ(refusal(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)), file + ": it has no vertices ('v' lines)");
  AssetManager assets;
  try {
    (void)import_model(folder_ / "missing.obj", assets);
    ADD_FAILURE() << "a missing file loaded";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()), (folder_ / "missing.obj").string() + ": no such file");
  }
}

// Ear clipping costs the square of a face's corners: a file whose faces of
// more than four corners exceed kMaxObjClipWork in all is refused before it
// is parsed, naming the line where the sum passed it and the largest face; a
// single 4,096-gon, within it, loads.
TEST_F(ObjText, FacesTooCostlyToCutAreRefusedNamingTheLines) {
  const auto polygon = [](std::size_t corners, std::size_t copies) {
    std::string text = "# a circle\n";
    for (std::size_t i = 0; i < corners; ++i) {
      const double a = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(corners);
      text.append("v ").append(std::to_string(std::cos(a))).append(" ").append(std::to_string(std::sin(a))).append(" 0\n");
    }
    std::string face = "f";
    for (std::size_t i = 1; i <= corners; ++i) face.append(" ").append(std::to_string(i));
    for (std::size_t c = 0; c < copies; ++c) text += face + "\n";
    return text;
  };
  // 1,024-gons: 1,024 of them reach 2^30 exactly, the 1,025th passes it.
  EXPECT_EQ(refusal(polygon(1024, 1100)), (folder_ / "model.obj").string() +
                                              ": its faces are too large to cut into triangles: by line 2050 their corners, squared and summed, "
                                              "exceed 1073741824 (the largest, on line 1026, has 1024)");
  const fs::path file = write("circle.obj", polygon(4096, 1));
  AssetManager assets;
  const ModelImport model = import_model(file, assets);
  EXPECT_EQ(drawn_triangles(assets, model), 4096u - 2);
}

// Without normals, faces that share a position ('v') are smooth there even
// where their texture coordinates differ (a seam); with them, as given.
TEST_F(ObjText, MissingNormalsAreSmoothAcrossTextureSeams) {
  // Two triangles folded 90 degrees along the edge (0,0,0)-(0,1,0), each with
  // texture coordinates of its own.
  const fs::path file = write("fold.obj",
                              "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 1\n"
                              "vt 0 0\nvt 0 1\nvt 1 0\nvt 0.5 0\nvt 0.5 1\nvt 0 0.5\n"
                              "f 1/1 3/3 2/2\nf 1/4 2/5 4/6\n");
  AssetManager assets;
  const ModelImport model = import_model(file, assets);
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
  const MeshAsset& asset = assets.mesh_asset(model.asset);
  const Primitive& p = asset.meshes.at(0).primitives.at(0);
  const auto vertices = asset.vertices(p);
  ASSERT_EQ(vertices.size(), 6u) << "a seam: the fold's two corners are two vertices each";
  for (const Vertex& v : vertices) {
    if (v.position.x == 0.0f && v.position.z == 0.0f) {
      EXPECT_NEAR(v.normal.x, std::sqrt(0.5f), 1e-5f) << "the fold's edge is the average of both faces";
      EXPECT_NEAR(v.normal.z, std::sqrt(0.5f), 1e-5f);
    }
  }
}

TEST_F(ObjText, VertexColoursTextureCoordinatesAndMaterialsPerFace) {
  write("two.mtl", "newmtl red\nKd 1 0 0\nPr 0.3\nPm 0.8\nnewmtl plain\nKd 0.5 0.5 0.5\n");
  const fs::path file = write("two.obj",
                              "mtllib two.mtl\n"
                              "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 1 1 1\n"
                              "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                              "usemtl red\nf 1/1/1 2/2/1 3/3/1\nusemtl plain\nf 2/2/1 4/2/1 3/3/1\n");
  AssetManager assets;
  ImportOptions options;
  options.convention = MaterialConvention::Gltf;
  const ModelImport model = import_model(file, assets, options);
  EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
  const MeshAsset& asset = assets.mesh_asset(model.asset);
  ASSERT_EQ(asset.meshes.size(), 1u);
  ASSERT_EQ(asset.meshes[0].primitives.size(), 2u) << "one primitive per material";
  const Material& red = asset.materials.at(asset.meshes[0].primitives[0].material);
  EXPECT_EQ(red.name, "red");
  EXPECT_EQ(red.base_color_factor, glm::vec4(1, 0, 0, 1));
  EXPECT_FLOAT_EQ(red.roughness_factor, 0.3f);
  EXPECT_FLOAT_EQ(red.metallic_factor, 0.8f);
  const Material& plain = asset.materials.at(asset.meshes[0].primitives[1].material);
  EXPECT_FLOAT_EQ(plain.roughness_factor, 0.5f) << "no Pr and no Ns: the default roughness";
  for (const Vertex& v : asset.vertices(asset.meshes[0].primitives[0])) {
    if (v.position == glm::vec3(0, 1, 0)) {
      EXPECT_EQ(v.color, (std::array<std::uint16_t, 4>{0, 0, 65535, 65535}));
      EXPECT_EQ(v.uv0, glm::vec2(0, 0)) << "OBJ's V points up the image, Atrium's down";
    }
  }
}

}  // namespace
}  // namespace atrium::assets
