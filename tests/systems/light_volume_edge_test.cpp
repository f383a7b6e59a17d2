// Cases where volume- and radius-based techniques classically go wrong, each
// rendered by every mode and compared with forward: the camera inside a light's
// sphere, a sphere crossing the near plane, and one crossing the far plane.
#include <memory>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "components/camera.hpp"
#include "support/gl_test.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium {
namespace {

constexpr glm::ivec2 kSize{160, 90};

struct EdgeCase {
  const char* name;
  assets::SceneLight light;
  float far_plane;
};

// A floor and a back wall, seen from (0, 0.5, 5) looking along -Z.
std::unique_ptr<World> make_world(const EdgeCase& c, const std::string& mode) {
  assets::AssetManager manager;
  assets::MeshAsset room;
  assets::Material material;
  material.base_color_factor = glm::vec4(0.8f, 0.8f, 0.75f, 1.0f);
  material.metallic_factor = 0.0f;
  material.roughness_factor = 0.5f;
  room.materials.push_back(material);
  assets::Primitive geometry = assets::shapes::grid(glm::vec3(-10, 0, 10), glm::vec3(20, 0, 0), glm::vec3(0, 0, -20), 20, 20, 1.0f);
  assets::shapes::append(geometry, assets::shapes::grid(glm::vec3(-10, 0, -10), glm::vec3(20, 0, 0), glm::vec3(0, 6, 0), 20, 6, 1.0f),
                         glm::mat4(1.0f));
  room.meshes.push_back({"room", {geometry}});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(room)), 0, Transform{}});
  scene.lights.push_back(c.light);
  scene.views.push_back({"eye", glm::vec3(0.0f, 0.5f, 5.0f), 0.0f, -8.0f});
  auto world = std::make_unique<World>(std::move(manager), std::move(scene), WorldOptions{"", std::nullopt, mode, 1, kSize});
  world->registry().view<Camera>().each([&](Camera& camera) { camera.far_plane = c.far_plane; });
  return world;
}

assets::Image render(const EdgeCase& c, const std::string& mode) {
  const auto world = make_world(c, mode);
  world->frame(0.0);
  return world->renderer().read_output();
}

const EdgeCase kCases[] = {
    {"camera_inside", {glm::vec3(0.3f, 0.8f, 4.5f), glm::vec3(1.0f, 0.9f, 0.8f), 0.6f, 6.0f}, 200.0f},
    // Centre 1.02 m ahead, radius 1: the sphere reaches 2 cm in front of the
    // camera, through the near plane (5 cm), with the camera just outside.
    {"crosses_near_plane", {glm::vec3(0.0f, 0.5f, 3.98f), glm::vec3(0.9f, 1.0f, 0.8f), 0.15f, 1.0f}, 200.0f},
    // Centre 4.5 m ahead, radius 2, far plane at 6 m.
    {"crosses_far_plane", {glm::vec3(0.0f, 0.4f, 0.5f), glm::vec3(0.8f, 0.9f, 1.0f), 1.5f, 2.0f}, 6.0f},
};

class VolumeEdgeCase : public testing::GlTest, public ::testing::WithParamInterface<std::tuple<std::string, int>> {};

TEST_P(VolumeEdgeCase, MatchesForward) {
  const auto& [mode, index] = GetParam();
  const EdgeCase& c = kCases[index];
  const assets::Image reference = render(c, "forward");
  double lit = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) lit += assets::luma(reference, x, y) > 0.15;
  }
  ASSERT_GT(lit, kSize.x * kSize.y * 0.02) << c.name << ": the light must visibly reach the scene";
  const assets::Image image = render(c, mode);
  assets::write_png(std::string("edge_") + c.name + "_" + mode + ".png", image);
  EXPECT_GE(assets::psnr(reference, image), 40.0) << mode << " " << c.name;
  EXPECT_LE(assets::max_channel_difference(reference, image), 8) << mode << " " << c.name;
}

std::vector<std::string> non_forward_modes() {
  std::vector<std::string> modes;
  for (const auto& info : lighting::technique_table()) {
    if (info.name != "forward") modes.emplace_back(info.name);
  }
  return modes;
}

INSTANTIATE_TEST_SUITE_P(Modes, VolumeEdgeCase, ::testing::Combine(::testing::ValuesIn(non_forward_modes()), ::testing::Values(0, 1, 2)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param) + "_" + kCases[std::get<1>(info.param)].name;
                           for (char& ch : name) if (ch == '-') ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace atrium
