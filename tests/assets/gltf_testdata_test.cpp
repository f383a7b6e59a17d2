// Every file in ../shared/testdata/gltf (written by Blender and by tinygltf's
// authors): valid ones load with the triangle and material counts their JSON
// declares, less the triangles of zero area (both counted independently with a
// numpy script), which are skipped with one warning; broken ones are refused
// with a message that names the file.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "assets/gltf_import.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

fs::path testdata() { return fs::path(ATRIUM_TESTDATA_DIR) / "gltf"; }

std::size_t triangles(const AssetManager& assets, MeshAssetHandle handle) {
  std::size_t total = 0;
  for (const Mesh& mesh : assets.mesh_asset(handle).meshes) total += triangle_count(mesh);
  return total;
}

struct Expected {
  const char* file;
  std::size_t triangles;  // declared
  std::size_t zero_area;  // of those
  std::size_t materials;
};

class ValidFile : public ::testing::TestWithParam<Expected> {};

TEST_P(ValidFile, LoadsWithItsTrianglesAndMaterials) {
  const Expected& e = GetParam();
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / e.file, assets);
  EXPECT_EQ(triangles(assets, imported.asset), e.triangles - e.zero_area);
  const auto skipped = std::count_if(imported.warnings.begin(), imported.warnings.end(), [&](const std::string& w) {
    return w.find(std::to_string(e.zero_area) + " of " + std::to_string(e.triangles) + " triangles have zero area") != std::string::npos;
  });
  EXPECT_EQ(skipped, e.zero_area > 0 ? 1 : 0) << "one warning for the whole file";
  const auto& materials = assets.mesh_asset(imported.asset).materials;
  // A primitive without a material gets one default material appended.
  std::size_t named = 0;
  for (const Material& m : materials) named += m.name != "default";
  EXPECT_EQ(named, e.materials);
  const MeshAsset& asset = assets.mesh_asset(imported.asset);
  for (const Mesh& mesh : asset.meshes) {
    for (const Primitive& p : mesh.primitives) {
      for (const Vertex& v : asset.vertices(p)) {
        ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-3f) << e.file;
        ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-3f) << e.file;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Testdata, ValidFile,
    ::testing::Values(Expected{"blender-exports/geosphere.gltf", 1280, 0, 1}, Expected{"blender-exports/primitives.gltf", 3636, 0, 6},
                      Expected{"blender-exports/subpass_scene_opaque.gltf", 11132, 4100, 5},
                      Expected{"blender-exports/subpass_scene_transparent.gltf", 164, 0, 1},
                      Expected{"blender-exports/teapot.gltf", 9128, 8, 1}, Expected{"blender-exports/terrain.gltf", 5202, 0, 1},
                      Expected{"blender-exports/torusknot.gltf", 2880, 0, 1}, Expected{"tinygltf/Cube/Cube.gltf", 12, 0, 1},
                      Expected{"tinygltf/Cube-texture-ext/Cube-textransform.gltf", 12, 0, 2}, Expected{"tinygltf/box01.glb", 12, 0, 1},
                      Expected{"tinygltf/zero-sized-bin-chunk-issue-440.glb", 1, 0, 1}, Expected{"tinygltf/issue-416.gltf", 0, 0, 0},
                      Expected{"tinygltf/issue-492.glb", 0, 0, 0}),
    [](const auto& info) {
      std::string name = fs::path(info.param.file).stem().string();
      for (char& c : name) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

TEST(GltfTestdata, InstancedMeshesBecomeOneInstancePerNode) {
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / "blender-exports/subpass_scene_opaque.gltf", assets);
  EXPECT_GT(imported.instances.size(), assets.mesh_asset(imported.asset).meshes.size());
  EXPECT_LT(imported.bounds.min.x, imported.bounds.max.x);
}

TEST(GltfTestdata, MaterialFactorsAreRead) {
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / "blender-exports/subpass_scene_transparent.gltf", assets);
  const Material& m = assets.mesh_asset(imported.asset).materials.front();
  EXPECT_TRUE(m.double_sided);
  EXPECT_FLOAT_EQ(m.base_color_factor.r, 0.6399999856948853f);
  EXPECT_FLOAT_EQ(m.metallic_factor, 0.0f);
  EXPECT_FLOAT_EQ(m.roughness_factor, 0.5f);
}

TEST(GltfTestdata, CubeTexturesAreDecodedInTheirColourSpaces) {
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / "tinygltf/Cube/Cube.gltf", assets);
  const Material& m = assets.mesh_asset(imported.asset).materials.at(0);
  ASSERT_TRUE(m.base_color_texture.valid());
  ASSERT_TRUE(m.metallic_roughness_texture.valid());
  EXPECT_EQ(assets.texture(m.base_color_texture.texture).color_space, ColorSpace::Srgb);
  EXPECT_EQ(assets.texture(m.metallic_roughness_texture.texture).color_space, ColorSpace::Linear);
  EXPECT_GT(assets.texture(m.base_color_texture.texture).image.width, 1);
  EXPECT_EQ(imported.images, 2u);
}

TEST(GltfTestdata, TextureTransformIsRead) {
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / "tinygltf/Cube-texture-ext/Cube-textransform.gltf", assets);
  bool transformed = false;
  for (const Material& m : assets.mesh_asset(imported.asset).materials) {
    for (const TextureSlot* slot : {&m.base_color_texture, &m.metallic_roughness_texture}) {
      transformed = transformed || slot->uv_transform != glm::mat3(1.0f);
    }
  }
  EXPECT_TRUE(transformed);
}

TEST(GltfTestdata, UndecodableImageUriIsAWarning) {
  AssetManager assets;
  const ModelImport imported = import_gltf(testdata() / "tinygltf/issue-416.gltf", assets);
  ASSERT_FALSE(imported.warnings.empty());
  EXPECT_NE(imported.warnings.front().find("issue-416.gltf"), std::string::npos);
}

class BrokenFile : public ::testing::TestWithParam<const char*> {};

TEST_P(BrokenFile, IsRefusedWithAMessageNamingTheFile) {
  ASSERT_TRUE(fs::is_regular_file(testdata() / "tinygltf/BoundsChecking" / GetParam())) << "testdata missing";
  AssetManager assets;
  try {
    (void)import_gltf(testdata() / "tinygltf/BoundsChecking" / GetParam(), assets);
    FAIL() << GetParam() << " was accepted";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam()), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(BoundsChecking, BrokenFile,
                         ::testing::Values("integer-out-of-bounds.gltf", "invalid-buffer-index.gltf",
                                           "invalid-buffer-view-index.gltf", "invalid-primitive-indices.gltf"),
                         [](const auto& info) {
                           std::string name = fs::path(info.param).stem().string();
                           for (char& c : name) if (c == '-') c = '_';
                           return name;
                         });

TEST(GltfTestdata, MissingFileIsNamed) {
  AssetManager assets;
  EXPECT_THROW((void)import_gltf("/nonexistent/model.gltf", assets), ImportError);
}

}  // namespace
}  // namespace atrium::assets
