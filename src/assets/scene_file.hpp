// Scene files (scenes/*.json, specified in docs/scene-format.md) and glTF models
// opened directly: both become a SceneDescription, with the models imported into
// the AssetManager. Errors name the file, the JSON path of the bad value, and
// what was expected.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "assets/asset_manager.hpp"
#include "assets/gltf_import.hpp"
#include "assets/scene.hpp"

namespace atrium::assets {

class SceneFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadReport {
  std::vector<std::string> warnings;
  ImportTimings timings;
  std::size_t images = 0;
};

// Throws SceneFileError (bad JSON or values, missing models) or ImportError.
[[nodiscard]] SceneDescription load_scene_file(const std::filesystem::path& path, AssetManager& assets, LoadReport& report,
                                               const ProgressCallback& progress = {});

// Five views of a box: four from outside, looking at its centre obliquely
// (front, side, corner, top), and one inside it (off the plane of a flat box).
[[nodiscard]] std::vector<NamedView> framing_views(glm::vec3 bounds_min, glm::vec3 bounds_max);

// A glTF model as a scene: its instances and KHR_lights_punctual lights, five
// views framing its bounds, and `extra_lights` generated lights inside them.
[[nodiscard]] SceneDescription load_model_scene(const std::filesystem::path& path, AssetManager& assets,
                                                std::uint32_t extra_lights, LoadReport& report,
                                                const ProgressCallback& progress = {});

}  // namespace atrium::assets
