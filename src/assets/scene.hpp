// A scene as data, before it becomes entities: mesh instances, lights, the five
// stored views and global settings. The built-in scene builds one in code; scene
// files and glTF import produce the same structure.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/handles.hpp"
#include "components/transform.hpp"

namespace atrium::assets {

struct SceneInstance {
  MeshAssetHandle asset;
  std::uint32_t mesh = 0;
  Transform transform;
};

struct SceneLight {
  glm::vec3 position{0.0f};
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  std::optional<float> radius;  // derived from colour and intensity when absent
};

struct NamedView {
  std::string name;
  glm::vec3 position{0.0f};
  float yaw_degrees = 0.0f;
  float pitch_degrees = 0.0f;
};

struct SceneDescription {
  std::string name;
  std::vector<SceneInstance> instances;
  std::vector<SceneLight> lights;
  std::vector<NamedView> views;
  glm::vec3 ambient{0.03f};        // ambient term = ambient * albedo * occlusion
  glm::vec3 background{0.0f};      // linear HDR colour behind all geometry
  float exposure = 1.0f;
  std::string default_mode = "forward";
  glm::vec3 bounds_min{0.0f};
  glm::vec3 bounds_max{0.0f};
};

// Seeded light generator: `count` lights uniformly inside a box, hue drawn from
// a fully saturated palette, intensity uniform in [intensity_min, intensity_max].
struct LightGenerator {
  std::uint32_t count = 0;
  std::uint32_t seed = 1;
  glm::vec3 box_min{-1.0f};
  glm::vec3 box_max{1.0f};
  float intensity_min = 1.0f;
  float intensity_max = 1.0f;
  std::optional<float> radius;
};
[[nodiscard]] std::vector<SceneLight> generate_lights(const LightGenerator& generator);

}  // namespace atrium::assets
