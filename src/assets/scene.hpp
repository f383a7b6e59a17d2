// A scene as data, before it becomes entities: mesh instances, lights, the five
// stored views and global settings. The built-in scene builds one in code; scene
// files and glTF import produce the same structure.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/handles.hpp"
#include "base/box.hpp"
#include "components/transform.hpp"

namespace atrium::assets {

struct SceneInstance {
  MeshAssetHandle asset;
  std::uint32_t mesh = 0;
  Transform transform;
};

enum class LightKind : std::uint8_t { Point, Spot, Directional };

struct SceneLight {
  glm::vec3 position{0.0f};
  glm::vec3 color{1.0f};
  float intensity = 1.0f;       // W/sr for point and spot lights, W/m^2 for directional
  std::optional<float> radius;  // derived from colour and intensity when absent
  LightKind kind = LightKind::Point;
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot and directional: where the light points
  float inner_cone = 0.0f;                 // spot: radians from the axis, full intensity inside
  float outer_cone = 0.7853982f;           // spot: radians from the axis, dark outside
  bool generated = false;                  // made by a LightGenerator (and animated in the demo)
};

struct NamedView {
  std::string name;
  glm::vec3 position{0.0f};
  float yaw_degrees = 0.0f;
  float pitch_degrees = 0.0f;
};

// Seeded light generator: `count` point lights uniformly inside a box, colour
// fixed or a random saturated hue, intensity uniform in [intensity_min,
// intensity_max], radius uniform in [radius_min, radius_max] when given
// (derived from colour and intensity otherwise).
struct LightGenerator {
  std::uint32_t count = 0;
  std::uint32_t seed = 1;
  glm::vec3 box_min{-1.0f};
  glm::vec3 box_max{1.0f};
  float intensity_min = 1.0f;
  float intensity_max = 1.0f;
  std::optional<glm::vec2> radius_range;
  std::optional<glm::vec3> color;
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
  // Where full-screen passes run ("fragment", "compute", "auto"); empty: not
  // set. Checked against the names by the World, like the mode.
  std::string lighting_stage;
  // Every instance's triangles, world space (empty: none); the World seeds
  // the SceneBounds resource with it, which the bounds system keeps current.
  Box bounds;
  // Fills the scene up to --lights N: the scene's own generator, or one over its bounds.
  std::optional<LightGenerator> fill_generator;
  // A scene file's "systems": settings of optional systems by name
  // (components/system_options.hpp).
  std::map<std::string, double> system_options;
};

// Sets the scene's light count to `count`: its listed lights first (cut when
// there are more), then lights from its fill generator (the first of a scene
// file's generators; the bounds when none). Growing regenerates the generated
// lights from the start of the fill generator's sequence, so the lights it had
// stay where they were.
void resize_lights(SceneDescription& scene, std::uint32_t count);

[[nodiscard]] std::vector<SceneLight> generate_lights(const LightGenerator& generator);

}  // namespace atrium::assets
