// Cases where volume- and radius-based techniques classically go wrong, each
// rendered by every mode and compared with forward: the camera inside a light's
// sphere, a sphere crossing the near plane, one crossing the far plane, spot and
// directional lights, alpha-blended geometry in front of the lit scene, and
// small lights that reach only that glass (its lists must come from the glass,
// not from the opaque surfaces behind it).
#include <algorithm>
#include <iterator>
#include <memory>
#include <string_view>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "components/camera.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

using testing::kSize;

struct EdgeCase {
  const char* name;
  std::vector<assets::SceneLight> lights;
  float far_plane = 200.0f;
  bool blended_panes = false;
  float near_plane = 0.05f;
  glm::vec3 eye{0.0f, 0.5f, 5.0f};
  float pitch_degrees = -8.0f;
};

// A floor and a back wall, seen from (0, 0.5, 5) looking along -Z.
std::unique_ptr<World> make_world(const EdgeCase& c, const std::string& mode,
                                  GBufferLayout layout = GBufferLayout::Full) {
  assets::AssetManager manager;
  assets::MeshAsset room;
  assets::Material material;
  material.base_color_factor = glm::vec4(0.8f, 0.8f, 0.75f, 1.0f);
  material.metallic_factor = 0.0f;
  material.roughness_factor = 0.5f;
  room.materials.push_back(material);
  assets::Geometry geometry = assets::shapes::grid(glm::vec3(-10, 0, 10), glm::vec3(20, 0, 0), glm::vec3(0, 0, -20), 20, 20, 1.0f);
  assets::shapes::append(geometry, assets::shapes::grid(glm::vec3(-10, 0, -10), glm::vec3(20, 0, 0), glm::vec3(0, 6, 0), 20, 6, 1.0f),
                         glm::mat4(1.0f));
  room.meshes.push_back({"room", {assets::add_geometry(room, geometry, 0)}});
  // Two overlapping tinted panes; drawn after lighting, back to front.
  assets::Material glass = material;
  glass.alpha_mode = assets::AlphaMode::Blend;
  glass.double_sided = true;
  glass.base_color_factor = glm::vec4(0.2f, 0.5f, 1.0f, 0.5f);
  room.materials.push_back(glass);
  glass.base_color_factor = glm::vec4(1.0f, 0.4f, 0.2f, 0.4f);
  room.materials.push_back(glass);
  for (std::uint32_t pane = 0; pane < 2; ++pane) {
    assets::Geometry quad = assets::shapes::grid(glm::vec3(-1.0f + 0.8f * static_cast<float>(pane), 0.0f, 1.5f - static_cast<float>(pane)),
                                                 glm::vec3(1.5f, 0, 0), glm::vec3(0, 1.2f, 0), 1, 1, 1.0f);
    room.meshes.push_back({"pane", {assets::add_geometry(room, std::move(quad), 1 + pane)}});
  }
  assets::SceneDescription scene;
  const assets::MeshAssetHandle handle = manager.add_mesh_asset(std::move(room));
  scene.instances.push_back({handle, 0, Transform{}});
  if (c.blended_panes) {
    scene.instances.push_back({handle, 1, Transform{}});
    scene.instances.push_back({handle, 2, Transform{}});
  }
  scene.lights = c.lights;
  scene.views.push_back({"eye", c.eye, 0.0f, c.pitch_degrees});
  auto world = std::make_unique<World>(std::move(manager), std::move(scene), WorldOptions{.scene = "", .mode = mode, .size = kSize, .technique_options = testing::with_layout(layout)});
  world->registry().view<Camera>().each([&](Camera& camera) {
    camera.near_plane = c.near_plane;
    camera.far_plane = c.far_plane;
  });
  return world;
}

assets::Image render(const EdgeCase& c, const std::string& mode, GBufferLayout layout = GBufferLayout::Full) {
  const auto world = make_world(c, mode, layout);
  world->frame(0.0);
  return world->renderer().read_output();
}

assets::SceneLight point(glm::vec3 position, glm::vec3 color, float intensity, float radius) {
  return {position, color, intensity, radius};
}

assets::SceneLight spot() {
  assets::SceneLight light{glm::vec3(-1.0f, 3.0f, 1.0f), glm::vec3(1.0f, 0.8f, 0.6f), 6.0f, 8.0f};
  light.kind = assets::LightKind::Spot;
  light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.4f));
  light.inner_cone = 0.25f;
  light.outer_cone = 0.5f;
  return light;
}

assets::SceneLight sun() {
  assets::SceneLight light{glm::vec3(0.0f), glm::vec3(0.6f, 0.7f, 1.0f), 0.4f, std::nullopt};
  light.kind = assets::LightKind::Directional;
  light.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f));
  return light;
}

assets::SceneLight evening_sun() {
  assets::SceneLight light{glm::vec3(0.0f), glm::vec3(1.0f, 0.6f, 0.3f), 0.3f, std::nullopt};
  light.kind = assets::LightKind::Directional;
  light.direction = glm::normalize(glm::vec3(0.8f, -0.3f, -0.5f));
  return light;
}

// A lattice of small lights just above the floor: many of their spheres cross
// tile and cluster boundaries, where a culling bug would cut light off.
std::vector<assets::SceneLight> straddling_lights() {
  std::vector<assets::SceneLight> lights;
  for (int i = 0; i < 8; ++i) {
    for (int j = 0; j < 8; ++j) {
      const glm::vec3 position(-3.5f + static_cast<float>(i), 0.15f, 1.5f - static_cast<float>(j) * 1.3f);
      lights.push_back(point(position, glm::vec3(0.3f + 0.1f * static_cast<float>(i % 3), 0.6f, 0.9f), 0.04f, 0.9f));
    }
  }
  return lights;
}

// Small lights just in front of the panes, reaching them but not the wall 10 m
// behind: a pane's tile or cluster must list them though no opaque pixel near
// them does (the floor below is out of their reach too).
std::vector<assets::SceneLight> lights_at_the_panes() {
  std::vector<assets::SceneLight> lights;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 3; ++j) {
      const glm::vec3 position(-0.9f + 0.45f * static_cast<float>(i), 0.55f + 0.3f * static_cast<float>(j), 1.75f - 0.2f * static_cast<float>(i));
      lights.push_back(point(position, glm::vec3(1.0f, 0.7f + 0.1f * static_cast<float>(j), 0.5f), 0.2f, 0.45f));
    }
  }
  return lights;
}

const EdgeCase kCases[] = {
    {"camera_inside", {point(glm::vec3(0.3f, 0.8f, 4.5f), glm::vec3(1.0f, 0.9f, 0.8f), 0.6f, 6.0f)}},
    // Centre 1.02 m ahead, radius 1: the sphere reaches 2 cm in front of the
    // camera, through the near plane (5 cm), with the camera just outside.
    {"crosses_near_plane", {point(glm::vec3(0.0f, 0.5f, 3.98f), glm::vec3(0.9f, 1.0f, 0.8f), 0.15f, 1.0f)}},
    // Centre 4.5 m ahead, radius 2, far plane at 6 m.
    {"crosses_far_plane", {point(glm::vec3(0.0f, 0.4f, 0.5f), glm::vec3(0.8f, 0.9f, 1.0f), 1.5f, 2.0f)}, 6.0f},
    {"spot_and_directional", {spot(), sun(), point(glm::vec3(2.0f, 1.0f, 0.0f), glm::vec3(0.4f, 1.0f, 0.4f), 0.5f, 4.0f)}},
    {"blended_panes", {point(glm::vec3(0.0f, 1.5f, 2.5f), glm::vec3(1.0f), 1.0f, 6.0f), sun()}, 200.0f, true},
    // 2 cm from the back wall, looking at it, with the far plane 1000x the near.
    {"close_to_wall", {point(glm::vec3(0.3f, 0.8f, -9.7f), glm::vec3(1.0f, 0.8f, 0.6f), 0.2f, 1.5f)}, 20.0f, false, 0.02f,
     glm::vec3(0.0f, 0.8f, -9.98f), 0.0f},
    {"straddling_edges", straddling_lights()},
    {"lights_at_the_panes", lights_at_the_panes(), 200.0f, true},
    // Each directional light is its own full-screen pass in the volume modes:
    // two of them, neither first in the buffer, between point lights.
    {"two_suns_among_lights", {point(glm::vec3(2.0f, 1.0f, 0.0f), glm::vec3(0.4f, 1.0f, 0.4f), 0.5f, 4.0f), sun(),
                               point(glm::vec3(-1.5f, 0.6f, 1.0f), glm::vec3(1.0f, 0.5f, 0.3f), 0.4f, 3.0f), evening_sun()}},
};

class VolumeEdgeCase : public testing::GlTest,
                       public ::testing::WithParamInterface<std::tuple<std::tuple<std::string, GBufferLayout>, int>> {};

TEST_P(VolumeEdgeCase, MatchesForward) {
  const auto& [mode_layout, index] = GetParam();
  const auto& [mode, layout] = mode_layout;
  const std::string name = testing::test_name(mode, layout);
  const EdgeCase& c = kCases[index];
  const assets::Image reference = render(c, "forward");
  double lit = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) lit += assets::luma(reference, x, y) > 0.15;
  }
  ASSERT_GT(lit, kSize.x * kSize.y * 0.02) << c.name << ": the light must visibly reach the scene";
  const assets::Image image = render(c, mode, layout);
  assets::write_png(std::string("edge_") + c.name + "_" + name + ".png", image);
  EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << name << " " << c.name;
  EXPECT_LE(assets::max_channel_difference(reference, image), 8) << name << " " << c.name;
}

INSTANTIATE_TEST_SUITE_P(Modes, VolumeEdgeCase,
                         ::testing::Combine(::testing::ValuesIn(testing::mode_layouts()), ::testing::Range(0, static_cast<int>(std::size(kCases)))),
                         [](const auto& info) {
                           const auto& mode_layout = std::get<0>(info.param);
                           return testing::test_name(std::get<0>(mode_layout), std::get<1>(mode_layout)) + "_" +
                                  kCases[std::get<1>(info.param)].name;
                         });

using BlendedPanes = testing::GlTest;

TEST_F(BlendedPanes, AreVisibleOverTheLitScene) {
  EdgeCase with = *std::find_if(std::begin(kCases), std::end(kCases), [](const EdgeCase& c) { return std::string_view(c.name) == "blended_panes"; });
  EdgeCase without = with;
  without.blended_panes = false;
  // The panes change the picture where they are: this is not a no-op test.
  EXPECT_LT(assets::psnr(render(with, "forward"), render(without, "forward")), 35.0);
}

}  // namespace
}  // namespace atrium
