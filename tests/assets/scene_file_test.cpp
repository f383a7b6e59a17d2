// Scene files: every field read as written, and every kind of mistake refused
// with the file, the JSON pointer of the bad value, and what was expected.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "assets/scene_file.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

class SceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("atrium_scene_test_" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& text) {
    const fs::path path = folder_ / "scene.json";
    std::ofstream(path) << text;
    return path;
  }
  SceneDescription load(const std::string& text) {
    report_ = {};
    return load_scene_file(write(text), assets_, report_);
  }
  std::string error(const std::string& text) {
    try {
      (void)load(text);
    } catch (const SceneFileError& e) {
      return e.what();
    }
    return "(no error)";
  }
  static std::string model(const char* relative) {
    return (fs::path(ATRIUM_TESTDATA_DIR) / "gltf" / relative).string();
  }

  fs::path folder_;
  AssetManager assets_;
  LoadReport report_;
};

TEST_F(SceneFile, ReadsModelsLightsGeneratorsViewsAndSettings) {
  const SceneDescription scene = load(R"({
    "name": "test",
    "models": [
      {"path": ")" + model("blender-exports/teapot.gltf") + R"(", "position": [10, 0, 0], "scale": 2},
      {"path": ")" + model("blender-exports/teapot.gltf") + R"(", "position": [-10, 0, 0], "rotation_degrees": [0, 90, 0]}
    ],
    "lights": [
      {"position": [1, 2, 3], "color": [1, 0.5, 0.25], "intensity": 2, "radius": 4},
      {"position": [0, 5, 0], "intensity": 1},
      {"type": "spot", "position": [0, 9, 0], "direction": [0, -1, 0], "intensity": 3, "inner_cone_degrees": 10, "outer_cone_degrees": 30},
      {"type": "directional", "direction": [0, -1, 1], "color": 0.5, "intensity": 0.2}
    ],
    "light_generators": [{"count": 20, "seed": 3, "box": {"min": [-1, 0, -1], "max": [1, 2, 1]}, "intensity": [0.5, 1], "radius": [2, 3]}],
    "views": [{"name": "a", "position": [0, 1, 5], "yaw_degrees": 10, "pitch_degrees": -5},
              {"name": "b", "position_in_bounds": [0.5, 0.5, 0.5]}],
    "ambient": [0.1, 0.2, 0.3], "background": 0.05, "exposure": 2, "default_mode": "forward"
  })");
  EXPECT_EQ(scene.name, "test");
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.instances[0].asset, scene.instances[1].asset) << "one model used twice is imported once";
  EXPECT_EQ(assets_.mesh_asset_count(), 1u);
  EXPECT_NEAR(scene.instances[0].transform.position.x, 10.0f, 1e-5f);
  // The file's scale multiplies the node's own (the teapot's node scales it too).
  EXPECT_NEAR(scene.instances[0].transform.scale.x, 2.0f * scene.instances[1].transform.scale.x, 1e-4f);
  ASSERT_EQ(scene.lights.size(), 24u);
  EXPECT_EQ(scene.lights[0].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(*scene.lights[0].radius, 4.0f);
  EXPECT_FALSE(scene.lights[1].radius.has_value());
  EXPECT_EQ(scene.lights[1].color, glm::vec3(1.0f));
  EXPECT_EQ(scene.lights[2].kind, LightKind::Spot);
  EXPECT_NEAR(scene.lights[2].outer_cone, glm::radians(30.0f), 1e-6f);
  EXPECT_EQ(scene.lights[3].kind, LightKind::Directional);
  EXPECT_NEAR(glm::length(scene.lights[3].direction), 1.0f, 1e-6f);
  for (std::size_t i = 4; i < 24; ++i) {
    EXPECT_TRUE(glm::all(glm::lessThanEqual(scene.lights[i].position, glm::vec3(1, 2, 1))));
    EXPECT_GE(*scene.lights[i].radius, 2.0f);
    EXPECT_LE(*scene.lights[i].radius, 3.0f);
  }
  ASSERT_EQ(scene.views.size(), 2u);
  EXPECT_EQ(scene.views[0].yaw_degrees, 10.0f);
  EXPECT_NEAR(scene.views[1].position.x, 0.5f * (scene.bounds.min.x + scene.bounds.max.x), 1e-4f);
  EXPECT_EQ(scene.ambient, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(scene.background, glm::vec3(0.05f));
  EXPECT_EQ(scene.exposure, 2.0f);
  EXPECT_LT(scene.bounds.min.x, -9.0f);
  EXPECT_GT(scene.bounds.max.x, 9.0f);
}

TEST_F(SceneFile, ResizingLightsKeepsListedOnesFirstThenUsesTheGenerator) {
  SceneDescription scene = load(R"({"lights": [{"position": [0, 0, 0], "intensity": 1}],
    "light_generators": [{"count": 2, "box": {"min": [0, 0, 0], "max": [1, 1, 1]}, "intensity": 1}]})");
  resize_lights(scene, 100);
  ASSERT_EQ(scene.lights.size(), 100u);
  EXPECT_EQ(scene.lights[0].position, glm::vec3(0.0f));
  for (const auto& light : scene.lights) EXPECT_TRUE(glm::all(glm::lessThanEqual(light.position, glm::vec3(1.0f))));
  resize_lights(scene, 0);
  EXPECT_TRUE(scene.lights.empty());
}

TEST_F(SceneFile, BuiltinCourtyardCanBeAModel) {
  const SceneDescription scene = load(R"({"models": [{"builtin": "atrium"}], "lights": [{"position": [0, 1, 0], "intensity": 1}]})");
  EXPECT_GT(scene.instances.size(), 100u);
  EXPECT_EQ(scene.lights.size(), 1u) << "lights come from the file only";
  EXPECT_EQ(scene.views.size(), 5u);
}

TEST_F(SceneFile, MistakesNameThePathAndWhatWasExpected) {
  const std::string file = (folder_ / "scene.json").string();
  EXPECT_EQ(error("{ \"lights\": [ "), file + ": not valid JSON (parse error at line 1, column 15: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal)");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0], "intensity": 1, "radius": -2}]})"),
            file + ": /lights/0/radius: expected a positive number, got -2");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0], "intensity": 1}]})"),
            file + ": /lights/0/position: expected an array of 3 numbers, got [0,0]");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, "x"], "intensity": 1}]})"),
            file + ": /lights/0/position/2: expected a number from -10000000 to 10000000, got \"x\"");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0]}]})"), file + ": /lights/0/intensity: is missing");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0], "intensity": -1}]})"),
            file + ": /lights/0/intensity: expected a positive number, got -1");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0], "intensity": 1}, {"position": [0, 0, 0], "intensity": 0}]})"),
            file + ": /lights/1/intensity: expected a positive number, got 0");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0], "intensity": 1, "radius": 0}]})"),
            file + ": /lights/0/radius: expected a positive number, got 0");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 1e308, 0], "intensity": 1}]})"),
            file + ": /lights/0/position/1: expected a number from -10000000 to 10000000, got 1e+308");
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 1e999, 0], "intensity": 1}]})"),
            file + ": not valid JSON (number overflow parsing '1e999')");
  EXPECT_EQ(error(R"({"lights": {"position": [0, 0, 0]}})"), file + ": /lights: expected an array, got {\"position\":[0,0,0]}");
  EXPECT_EQ(error(R"({"lights": [{"type": "area", "position": [0, 0, 0], "intensity": 1}]})"),
            file + ": /lights/0/type: expected \"point\", \"spot\" or \"directional\", got \"area\"");
  EXPECT_EQ(error(R"({"colour": 1})"),
            file + ": /colour: unknown key (expected one of: name, models, lights, light_generators, views, ambient, background, exposure, default_mode, lighting_stage, systems)");
  EXPECT_EQ(error(R"({"light_generators": [{"count": -5, "intensity": 1}]})"),
            file + ": /light_generators/0/count: expected a whole number from 0 to 1,048,576, got -5");
  EXPECT_EQ(error(R"({"light_generators": [{"count": 5, "intensity": [2, 1]}]})"),
            file + ": /light_generators/0/intensity: expected [min, max] with min <= max, got [2,1]");
  EXPECT_EQ(error(R"({"views": []})"), file + ": /views: expected 1 to 9 views, got 0");
  EXPECT_EQ(error(R"({"views": [{"name": "a"}]})"), file + ": /views/0/position: is missing (or give position_in_bounds)");
  EXPECT_EQ(error(R"({"exposure": 0})"), file + ": /exposure: expected a positive number, got 0");
  // A number of the right sign past a bound says which bound.
  EXPECT_EQ(error(R"({"lights": [{"position": [0, 0, 0], "intensity": 1e30}]})"),
            file + ": /lights/0/intensity: expected a positive number no greater than 1,000,000,000, got 1e+30");
  EXPECT_EQ(error(R"({"models": [{"builtin": "atrium", "scale": 1e-30}]})"),
            file + ": /models/0/scale: expected a positive number no less than 1e-06, got 1e-30");
  EXPECT_EQ(error(R"({"ambient": 2e6})"), file + ": /ambient: expected a non-negative number no greater than 1,000,000, got 2000000.0");
}

TEST_F(SceneFile, MissingModelSaysHowToFetchIt) {
  const std::string message = error(R"({"models": [{"path": "../assets/sponza/glTF/Sponza.gltf", "fetch": "scripts/fetch-scenes.sh sponza"}]})");
  EXPECT_NE(message.find("/models/0/path: "), std::string::npos) << message;
  EXPECT_NE(message.find("Sponza.gltf does not exist; fetch it with `scripts/fetch-scenes.sh sponza`"), std::string::npos) << message;
}

TEST_F(SceneFile, ThePrintedViewLineAndCameraValueGiveTheViewBack) {
  // What the window's c key prints, pasted into a scene file or given to --camera.
  const NamedView here{"here", glm::vec3(-3.25f, 1.5f, 12.125f), 97.5f, -12.25f};
  const SceneDescription scene = load(R"({"models": [{"builtin": "atrium"}], "views": [)" + view_json(here) + "]}");
  ASSERT_EQ(scene.views.size(), 1u);
  EXPECT_EQ(scene.views[0].name, "here");
  EXPECT_NEAR(glm::distance(scene.views[0].position, here.position), 0.0f, 1e-3f);
  EXPECT_NEAR(scene.views[0].yaw_degrees, here.yaw_degrees, 0.05f);
  EXPECT_NEAR(scene.views[0].pitch_degrees, here.pitch_degrees, 0.05f);
  const std::optional<NamedView> parsed = parse_camera_argument(camera_argument(here));
  ASSERT_TRUE(parsed);
  EXPECT_NEAR(glm::distance(parsed->position, here.position), 0.0f, 1e-3f);
  EXPECT_NEAR(parsed->yaw_degrees, here.yaw_degrees, 0.05f);
  EXPECT_NEAR(parsed->pitch_degrees, here.pitch_degrees, 0.05f);
  for (const char* bad : {"", "1,2,3,4", "1,2,3,4,5,6", "1,2,x,4,5", "1,2,3,4,91", "1,2,3,inf,5", "1,,3,4,5"}) {
    EXPECT_FALSE(parse_camera_argument(bad)) << bad;
  }
}

TEST_F(SceneFile, MissingFileIsNamed) {
  LoadReport report;
  EXPECT_THROW((void)load_scene_file(folder_ / "absent.json", assets_, report), SceneFileError);
}

TEST(ModelScene, AddsGeneratedLightsToTheModelsOwnAndFramesItWithFiveViews) {
  AssetManager assets;
  LoadReport report;
  const SceneDescription scene =
      load_model_scene(fs::path(ATRIUM_TESTDATA_DIR) / "gltf/blender-exports/torusknot.gltf", assets, 12, report);
  EXPECT_EQ(scene.lights.size(), 12u);
  EXPECT_EQ(scene.views.size(), 5u);
  EXPECT_EQ(scene.instances.size(), 1u);
}

}  // namespace
}  // namespace atrium::assets
