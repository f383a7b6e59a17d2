// One point light over a plane, rendered by the engine, against an independent
// CPU evaluation of the same BRDF, falloff, ambient, tone map and sRGB encoding
// at every pixel's centre. Largest allowed error: 2/255.
#include <cmath>

#include "app/world.hpp"
#include "assets/mesh_builder.hpp"
#include "components/frame_resources.hpp"
#include "support/gl_test.hpp"
#include "support/reference_shading.hpp"

namespace atrium {
namespace {

using AnalyticPlane = testing::GlTest;

struct Case {
  testing::ReferenceMaterial material;
  glm::vec3 light_position;
  glm::vec3 light_color;
  float intensity;
  std::optional<float> radius;
};

void check_case(const Case& c) {
  constexpr glm::ivec2 kSize{160, 90};
  constexpr float kHalf = 10.0f;
  assets::AssetManager manager;
  assets::MeshAsset plane;
  assets::Material material;
  material.base_color_factor = glm::vec4(c.material.albedo, 1.0f);
  material.metallic_factor = c.material.metallic;
  material.roughness_factor = c.material.roughness;
  plane.materials.push_back(material);
  plane.meshes.push_back({"plane", {assets::add_geometry(plane, assets::shapes::grid(glm::vec3(-kHalf, 0, kHalf), glm::vec3(2 * kHalf, 0, 0),
                                                                                     glm::vec3(0, 0, -2 * kHalf), 8, 8, 1.0f), 0)}});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(plane)), 0, Transform{}});
  scene.lights.push_back({c.light_position, c.light_color, c.intensity, c.radius});
  scene.views.push_back({"above", glm::vec3(0.0f, 4.0f, 4.5f), 0.0f, -50.0f});
  scene.ambient = glm::vec3(0.03f);
  scene.exposure = 1.3f;
  World world(std::move(manager), std::move(scene), {"", std::nullopt, "forward", 1, kSize});
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  const ViewState& view = world.registry().resource<ViewState>();
  const glm::mat4 inverse = glm::inverse(view.view_projection);

  const float radius = c.radius.value_or(lighting::light_radius_from_intensity(c.light_color, c.intensity));
  int compared = 0, worst = 0;
  double lit_pixels = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      // The pixel centre's ray (image rows run top to bottom, NDC y upward).
      const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f, 1.0f - (y + 0.5f) / kSize.y * 2.0f);
      glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f), far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 origin = glm::vec3(near) / near.w, target = glm::vec3(far) / far.w;
      const glm::vec3 dir = glm::normalize(target - origin);
      if (dir.y >= -1e-4f) continue;
      const float t = -origin.y / dir.y;
      const glm::vec3 p = origin + dir * t;
      if (std::abs(p.x) > kHalf - 0.05f || std::abs(p.z) > kHalf - 0.05f) continue;
      const glm::vec3 n(0, 1, 0), v = glm::normalize(view.camera_position - p);
      const glm::vec3 to_light = c.light_position - p;
      const float d = glm::length(to_light);
      const glm::vec3 radiance = c.light_color * c.intensity * lighting::light_attenuation(d, radius);
      const glm::vec3 hdr = testing::reference_brdf(n, v, to_light / d, c.material) * radiance + 0.03f * c.material.albedo;
      if (glm::length(radiance) > 0.0f) ++lit_pixels;
      for (int ch = 0; ch < 3; ++ch) {
        const int expected = static_cast<int>(std::lround(testing::reference_tonemap_to_srgb(hdr[ch] * 1.3) * 255.0));
        worst = std::max(worst, std::abs(expected - static_cast<int>(image.pixel(x, y)[ch])));
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, kSize.x * kSize.y / 2) << "the plane should fill most of the picture";
  EXPECT_GT(lit_pixels, compared / 10.0) << "the light should reach part of the plane";
  EXPECT_LE(worst, 2) << "largest channel error in 1/255 steps";
}

TEST_F(AnalyticPlane, DielectricRoughWithDerivedRadius) {
  check_case({{glm::vec3(0.8f, 0.6f, 0.4f), 0.0f, 0.7f}, glm::vec3(0.5f, 1.5f, -0.5f), glm::vec3(1.0f, 0.9f, 0.8f), 2.0f, std::nullopt});
}

TEST_F(AnalyticPlane, MetallicGlossyWithARadiusThatCutsInsideTheView) {
  check_case({{glm::vec3(0.9f, 0.7f, 0.3f), 1.0f, 0.3f}, glm::vec3(-1.0f, 1.0f, 0.0f), glm::vec3(0.6f, 0.8f, 1.0f), 3.0f, 3.0f});
}

}  // namespace
}  // namespace atrium
