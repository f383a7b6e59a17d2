// Scene files (scenes/*.json, specified in docs/scene-format.md) and glTF models
// opened directly: both become a SceneDescription, with the models imported into
// the AssetManager. Errors name the file, the JSON pointer of the bad value, and
// what was expected.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset_manager.hpp"
#include "assets/model_import.hpp"
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

// A view as a line for a scene file's "views" list (docs/scene-format.md):
// {"name": ..., "position": [x, y, z], "yaw_degrees": ..., "pitch_degrees": ...}
[[nodiscard]] std::string view_json(const NamedView& view);
// The same view as the value of --camera: "X,Y,Z,YAW,PITCH".
[[nodiscard]] std::string camera_argument(const NamedView& view);
// Reads "X,Y,Z,YAW,PITCH" (metres, degrees; pitch from -90 to 90); nullopt
// when the text is not five finite numbers in range.
[[nodiscard]] std::optional<NamedView> parse_camera_argument(std::string_view text);

// Five views of a box: four from outside, looking at its centre obliquely
// (front, side, corner, top), and one inside it (off the plane of a flat box).
[[nodiscard]] std::vector<NamedView> framing_views(const Box& bounds);

// A model file (glTF, OBJ, FBX, ...) as a scene: its instances and KHR_lights_punctual lights, five
// views framing its bounds, and `extra_lights` generated lights inside them.
[[nodiscard]] SceneDescription load_model_scene(const std::filesystem::path& path, AssetManager& assets,
                                                std::uint32_t extra_lights, LoadReport& report,
                                                const ProgressCallback& progress = {});

}  // namespace atrium::assets
