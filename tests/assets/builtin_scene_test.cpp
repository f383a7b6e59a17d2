#include <set>

#include <gtest/gtest.h>

#include "assets/builtin_scene.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium::assets {
namespace {

class BuiltinScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    manager_ = new AssetManager();
    scene_ = new SceneDescription(build_builtin_scene(*manager_));
  }
  static void TearDownTestSuite() {
    delete scene_;
    delete manager_;
  }
  static AssetManager* manager_;
  static SceneDescription* scene_;
};
AssetManager* BuiltinScene::manager_ = nullptr;
SceneDescription* BuiltinScene::scene_ = nullptr;

TEST_F(BuiltinScene, HasAtLeast200kTrianglesAcrossItsInstances) {
  std::size_t triangles = 0;
  for (const auto& instance : scene_->instances) {
    triangles += triangle_count(manager_->mesh_asset(instance.asset).meshes.at(instance.mesh));
  }
  EXPECT_GE(triangles, 200'000u);
}

TEST_F(BuiltinScene, HasAtLeastEightTexturedMaterialsWithEmissiveAndMaskedOnes) {
  const MeshAsset& asset = manager_->mesh_asset(scene_->instances.front().asset);
  ASSERT_GE(asset.materials.size(), 8u);
  int emissive = 0, masked = 0;
  for (const Material& m : asset.materials) {
    EXPECT_TRUE(m.base_color_texture.valid()) << m.name;
    EXPECT_TRUE(m.normal_texture.valid()) << m.name;
    EXPECT_TRUE(m.metallic_roughness_texture.valid()) << m.name;
    EXPECT_EQ(manager_->texture(m.base_color_texture.texture).color_space, ColorSpace::Srgb) << m.name;
    EXPECT_EQ(manager_->texture(m.normal_texture.texture).color_space, ColorSpace::Linear) << m.name;
    if (m.emissive_texture.valid()) ++emissive;
    if (m.alpha_mode == AlphaMode::Mask) {
      ++masked;
      EXPECT_TRUE(m.double_sided) << "banners are seen from both sides";
      // The banner's albedo alpha really cuts holes.
      const Image& albedo = manager_->texture(m.base_color_texture.texture).image;
      int holes = 0;
      for (std::size_t i = 3; i < albedo.rgba.size(); i += 4) holes += albedo.rgba[i] < 128;
      EXPECT_GT(holes, static_cast<int>(albedo.rgba.size() / 4 / 50)) << m.name;
    }
  }
  EXPECT_GE(emissive, 2);
  EXPECT_GE(masked, 1);
}

TEST_F(BuiltinScene, HasAtLeast128LightsAndFiveNamedViews) {
  EXPECT_GE(scene_->lights.size(), 128u);
  ASSERT_EQ(scene_->views.size(), 5u);
  std::set<std::string> names;
  for (const auto& view : scene_->views) names.insert(view.name);
  EXPECT_EQ(names.size(), 5u);
}

TEST_F(BuiltinScene, LightsAreInsideTheCourtWithFiniteRadii) {
  for (const auto& light : scene_->lights) {
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(light.position, scene_->bounds.min))) << light.position.x;
    EXPECT_TRUE(glm::all(glm::lessThanEqual(light.position, scene_->bounds.max))) << light.position.x;
    const float radius = lighting::light_radius_from_intensity(light.color, light.intensity);
    EXPECT_GT(radius, 2.0f);
    EXPECT_LT(radius, 15.0f);
  }
}

TEST(BuiltinSceneLights, CountIsHonouredAndPrefixesAgree) {
  EXPECT_TRUE(builtin_scene_lights(0).empty());
  const auto few = builtin_scene_lights(10);
  const auto many = builtin_scene_lights(1000);
  ASSERT_EQ(few.size(), 10u);
  ASSERT_EQ(many.size(), 1000u);
  for (std::size_t i = 0; i < few.size(); ++i) EXPECT_EQ(few[i].position, many[i].position);
}

TEST(BuiltinSceneLights, GeneratorIsSeededAndDeterministic) {
  LightGenerator generator;
  generator.count = 64;
  generator.seed = 7;
  generator.box_min = glm::vec3(-1.0f);
  generator.box_max = glm::vec3(1.0f);
  const auto a = generate_lights(generator);
  const auto b = generate_lights(generator);
  generator.seed = 8;
  const auto c = generate_lights(generator);
  ASSERT_EQ(a.size(), 64u);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
  EXPECT_NE(a[0].position, c[0].position);
}

}  // namespace
}  // namespace atrium::assets
