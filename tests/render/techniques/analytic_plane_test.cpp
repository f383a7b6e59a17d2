// One point light over a plane, rendered by the engine, against an independent
// CPU evaluation of the same BRDF, falloff, ambient, tone map and sRGB encoding
// at every pixel's centre (largest allowed error: 2/255); and with the lighting
// split, each deferred mode's diffuse and specular sums against the reference's
// two lobes; and the light pre-pass's light buffer against the reference BRDF's
// factors before any material.
#include <cmath>
#include <memory>

#include "app/world.hpp"
#include "assets/mesh_builder.hpp"
#include "components/frame_resources.hpp"
#include "support/gl_test.hpp"
#include "support/graph_capture.hpp"
#include "support/reference_shading.hpp"
#include "render/techniques/light_prepass/light_prepass.hpp"

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

using testing::kSize;
constexpr float kHalf = 10.0f;

std::unique_ptr<World> plane_world(const Case& c, const char* mode) {
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
  return std::make_unique<World>(std::move(manager), std::move(scene), WorldOptions{.scene = "", .mode = mode, .size = kSize});
}

// Where the ray through pixel centre (x, y_up) (GL's rows, bottom-up) meets the
// plane, or nothing when it misses the plane or lands on its edge.
std::optional<glm::vec3> plane_point(const ViewState& view, int x, int y_up) {
  const glm::vec2 ndc((x + 0.5f) / kSize.x * 2.0f - 1.0f, (y_up + 0.5f) / kSize.y * 2.0f - 1.0f);
  const glm::mat4 inverse = glm::inverse(view.view_projection);
  glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f), far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 origin = glm::vec3(near) / near.w, target = glm::vec3(far) / far.w;
  const glm::vec3 dir = glm::normalize(target - origin);
  if (dir.y >= -1e-4f) return std::nullopt;
  const glm::vec3 p = origin + dir * (-origin.y / dir.y);
  if (std::abs(p.x) > kHalf - 0.05f || std::abs(p.z) > kHalf - 0.05f) return std::nullopt;
  return p;
}

void check_case(const Case& c) {
  const std::unique_ptr<World> plane = plane_world(c, "forward");
  World& world = *plane;
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  const ViewState& view = world.registry().resource<ViewState>();
  const float radius = c.radius.value_or(lighting::light_radius_from_intensity(c.light_color, c.intensity));
  int compared = 0, worst = 0;
  double lit_pixels = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      // Image rows run top to bottom, GL's bottom-up.
      const auto hit = plane_point(view, x, kSize.y - 1 - y);
      if (!hit) continue;
      const glm::vec3 p = *hit;
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

// --split-lighting in every deferred mode: the diffuse and specular targets hold
// the reference's two lobes times the incoming light (HDR, before exposure), they
// add up with the ambient term to the lit HDR image, and the display image is
// the one drawn without the split.
void check_split(const Case& c) {
  const float radius = c.radius.value_or(lighting::light_radius_from_intensity(c.light_color, c.intensity));
  for (const char* mode : {"deferred", "deferred-radius", "light-volumes", "light-volumes-instanced", "tiled-deferred",
                           "clustered-deferred", "light-prepass"}) {
    SCOPED_TRACE(mode);
    const std::unique_ptr<World> plane = plane_world(c, mode);
    World& world = *plane;
    world.frame(0.0);
    const assets::Image unsplit = world.renderer().read_output();
    EXPECT_TRUE(world.renderer().read_hdr(render::MeshRenderer::HdrTarget::DiffuseLight).empty()) << "no sums while the split is off";
    world.registry().resource<RendererSettings>().technique_options.split_lighting = true;
    world.frame(0.0);
    EXPECT_GE(assets::psnr(unsplit, world.renderer().read_output()), 50.0);
    const auto hdr = world.renderer().read_hdr(render::MeshRenderer::HdrTarget::Color);
    const auto diffuse = world.renderer().read_hdr(render::MeshRenderer::HdrTarget::DiffuseLight);
    const auto specular = world.renderer().read_hdr(render::MeshRenderer::HdrTarget::SpecularLight);
    ASSERT_EQ(diffuse.size(), hdr.size());
    ASSERT_EQ(specular.size(), hdr.size());
    const ViewState& view = world.registry().resource<ViewState>();
    int compared = 0;
    float worst_diffuse = 0.0f, worst_specular = 0.0f, worst_sum = 0.0f, most_specular = 0.0f;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) {
        const auto p = plane_point(view, x, y);
        if (!p) continue;
        const glm::vec3 v = glm::normalize(view.camera_position - *p), to_light = c.light_position - *p;
        const float d = glm::length(to_light);
        const glm::vec3 radiance = c.light_color * c.intensity * lighting::light_attenuation(d, radius);
        glm::vec3 lobe_d, lobe_s;
        testing::reference_brdf_lobes(glm::vec3(0, 1, 0), v, to_light / d, c.material, lobe_d, lobe_s);
        const std::size_t i = static_cast<std::size_t>(y) * kSize.x + static_cast<std::size_t>(x);
        // Single-precision shading differs from the double-precision reference by
        // up to 2% at the peak of a sharp highlight (forward's image as much), and
        // half floats keep 11 significant bits: allow 3% and a small floor.
        for (int ch = 0; ch < 3; ++ch) {
          const float want_d = lobe_d[ch] * radiance[ch], want_s = lobe_s[ch] * radiance[ch];
          worst_diffuse = std::max(worst_diffuse, std::abs(diffuse[i][ch] - want_d) / (0.03f * want_d + 2e-3f));
          worst_specular = std::max(worst_specular, std::abs(specular[i][ch] - want_s) / (0.03f * want_s + 2e-3f));
          const float sum = 0.03f * c.material.albedo[ch] + diffuse[i][ch] + specular[i][ch];
          worst_sum = std::max(worst_sum, std::abs(hdr[i][ch] - sum) / (0.01f * sum + 2e-3f));
          most_specular = std::max(most_specular, want_s);
        }
        ++compared;
      }
    }
    EXPECT_GT(compared, kSize.x * kSize.y / 2);
    EXPECT_GT(most_specular, 0.05f) << "the highlight is in view";
    EXPECT_LE(worst_diffuse, 1.0f) << "diffuse sum, in units of the tolerance";
    EXPECT_LE(worst_specular, 1.0f) << "specular sum, in units of the tolerance";
    EXPECT_LE(worst_sum, 1.0f) << "ambient + diffuse + specular against the lit HDR image";
  }
}

TEST_F(AnalyticPlane, DielectricRoughWithDerivedRadius) {
  check_case({{glm::vec3(0.8f, 0.6f, 0.4f), 0.0f, 0.7f}, glm::vec3(0.5f, 1.5f, -0.5f), glm::vec3(1.0f, 0.9f, 0.8f), 2.0f, std::nullopt});
}

TEST_F(AnalyticPlane, MetallicGlossyWithARadiusThatCutsInsideTheView) {
  check_case({{glm::vec3(0.9f, 0.7f, 0.3f), 1.0f, 0.3f}, glm::vec3(-1.0f, 1.0f, 0.0f), glm::vec3(0.6f, 0.8f, 1.0f), 3.0f, 3.0f});
}

// The G-buffer keeps roughness in 8 bits: these roughnesses (102/255, 51/255)
// are stored exactly, so the highlights can be held to the reference.
TEST_F(AnalyticPlane, SplitSumsAreTheReferenceLobesInEveryDeferredMode) {
  check_split({{glm::vec3(0.8f, 0.6f, 0.4f), 0.0f, 0.4f}, glm::vec3(0.5f, 1.5f, -0.5f), glm::vec3(1.0f, 0.9f, 0.8f), 2.0f, std::nullopt});
  // A metal has no diffuse lobe: its diffuse target must stay black.
  check_split({{glm::vec3(0.9f, 0.7f, 0.3f), 1.0f, 0.2f}, glm::vec3(-1.0f, 1.0f, 0.0f), glm::vec3(0.6f, 0.8f, 1.0f), 3.0f, 3.0f});
}

// The light pre-pass sums, per light, factors that hold no material: the
// reference BRDF gives each through a material that isolates it. A metal with
// albedo 0 has f0 = 0, so its specular lobe is the f0-free factor; with albedo 1,
// f0 = 1 and the lobe is both specular factors; a white dielectric's diffuse
// lobe is 0.96 / pi times the diffuse factor.
// Per light-buffer target, the largest value either case expects somewhere.
std::array<float, 3> most_of_all{};

void check_light_buffer(const Case& c) {
  const std::unique_ptr<World> plane = plane_world(c, "light-prepass");
  World& world = *plane;
  std::vector<std::string> names;
  for (const char* target : techniques::LightPrepassTechnique::kLightBufferTargets) names.push_back(std::string("light-buffer.") + target);
  const std::shared_ptr<testing::Captured> captured = testing::capture_textures(world, names);
  world.frame(0.0);
  std::array<std::vector<glm::vec4>, 3> buffer;
  for (std::size_t t = 0; t < buffer.size(); ++t) {
    ASSERT_TRUE(captured->contains(names[t])) << names[t];
    buffer[t] = captured->at(names[t]);
  }
  const float radius = lighting::light_radius_from_intensity(c.light_color, c.intensity);
  const float roughness = c.material.roughness;
  const ViewState& view = world.registry().resource<ViewState>();
  int compared = 0;
  std::array<float, 3> worst{}, most{};
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const auto p = plane_point(view, x, y);
      if (!p) continue;
      const glm::vec3 n(0, 1, 0), v = glm::normalize(view.camera_position - *p), to_light = c.light_position - *p;
      const float d = glm::length(to_light);
      const glm::vec3 l = to_light / d;
      const glm::vec3 radiance = c.light_color * c.intensity * lighting::light_attenuation(d, radius);
      glm::vec3 white_diffuse, unused, metal_f0_zero, metal_f0_one;
      testing::reference_brdf_lobes(n, v, l, {glm::vec3(1.0f), 0.0f, roughness}, white_diffuse, unused);
      testing::reference_brdf_lobes(n, v, l, {glm::vec3(0.0f), 1.0f, roughness}, unused, metal_f0_zero);
      testing::reference_brdf_lobes(n, v, l, {glm::vec3(1.0f), 1.0f, roughness}, unused, metal_f0_one);
      const float pi = 3.14159265f;
      const std::array<glm::vec3, 3> want{white_diffuse * pi / 0.96f * radiance, (metal_f0_one - metal_f0_zero) * radiance,
                                          metal_f0_zero * radiance};
      const std::size_t i = static_cast<std::size_t>(y) * kSize.x + static_cast<std::size_t>(x);
      for (std::size_t t = 0; t < 3; ++t) {
        for (int ch = 0; ch < 3; ++ch) {
          // As for the split sums: single against double precision, half floats.
          worst[t] = std::max(worst[t], std::abs(buffer[t][i][ch] - want[t][ch]) / (0.03f * want[t][ch] + 2e-3f));
          most[t] = std::max(most[t], want[t][ch]);
        }
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, kSize.x * kSize.y / 2);
  for (std::size_t t = 0; t < 3; ++t) {
    SCOPED_TRACE(techniques::LightPrepassTechnique::kLightBufferTargets[t]);
    most_of_all[t] = std::max(most_of_all[t], most[t]);
    EXPECT_LE(worst[t], 1.0f) << "in units of the tolerance";
  }
}

TEST_F(AnalyticPlane, LightPrepassBufferHoldsTheBrdfFactorsBeforeMaterials) {
  check_light_buffer({{glm::vec3(0.8f), 0.0f, 0.35f}, glm::vec3(0.5f, 1.5f, -0.5f), glm::vec3(1.0f, 0.9f, 0.8f), 2.0f, std::nullopt});
  // Low behind the plane's far edge, seen against the view: near-grazing
  // reflection, where Schlick's f0-free term is large.
  check_light_buffer({{glm::vec3(0.8f), 0.0f, 0.35f}, glm::vec3(0.0f, 0.5f, -9.0f), glm::vec3(1.0f), 30.0f, std::nullopt});
  for (float most : most_of_all) EXPECT_GT(most, 0.02f) << "each factor is in view, well above the tolerance's floor";
}

}  // namespace
}  // namespace atrium
