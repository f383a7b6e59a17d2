#include "assets/scene_file.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "assets/builtin_scene.hpp"
#include "components/light.hpp"


namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Reads typed values out of the scene JSON; every error carries the file and
// the JSON pointer of the value, e.g. "scenes/x.json: /lights/3/radius: ...".
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& problem) const {
    throw SceneFileError(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + problem);
  }

  static std::string describe(const json& value) {
    std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 37) + "..." : text;
  }

  const json& member(const json& object, const std::string& pointer, const char* key) const {
    if (!object.contains(key)) fail(pointer + "/" + key, "is missing");
    return object.at(key);
  }

  // 10000000, 0.5, -1: the shortest form that reads back the same.
  static std::string compact_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
  }

  double number(const json& value, const std::string& pointer, double min, double max, const char* expected) const {
    if (!value.is_number()) fail(pointer, std::string("expected ") + expected + ", got " + describe(value));
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < min || v > max) fail(pointer, std::string("expected ") + expected + ", got " + describe(value));
    return v;
  }

  glm::vec3 vec3(const json& value, const std::string& pointer, double min = -1e7, double max = 1e7) const {
    if (!value.is_array() || value.size() != 3) fail(pointer, "expected an array of 3 numbers, got " + describe(value));
    glm::vec3 out;
    const std::string expected = "a number from " + compact_number(min) + " to " + compact_number(max);
    for (int i = 0; i < 3; ++i) {
      out[i] = static_cast<float>(number(value[static_cast<std::size_t>(i)], pointer + "/" + std::to_string(i), min, max, expected.c_str()));
    }
    return out;
  }

  // A colour: [r, g, b] with non-negative channels, or one number for grey.
  glm::vec3 color(const json& value, const std::string& pointer) const {
    if (value.is_number()) return glm::vec3(static_cast<float>(number(value, pointer, 0.0, 1e6, "a non-negative number")));
    return vec3(value, pointer, 0.0, 1e6);
  }

  glm::vec2 range(const json& value, const std::string& pointer, double min, double max, const char* expected) const {
    if (value.is_number()) return glm::vec2(static_cast<float>(number(value, pointer, min, max, expected)));
    if (!value.is_array() || value.size() != 2) fail(pointer, std::string("expected ") + expected + " or [min, max], got " + describe(value));
    const glm::vec2 r(static_cast<float>(number(value[0], pointer + "/0", min, max, expected)),
                      static_cast<float>(number(value[1], pointer + "/1", min, max, expected)));
    if (r.x > r.y) fail(pointer, "expected [min, max] with min <= max, got " + describe(value));
    return r;
  }

  std::string string(const json& value, const std::string& pointer) const {
    if (!value.is_string()) fail(pointer, "expected a string, got " + describe(value));
    return value.get<std::string>();
  }

  const json& array(const json& value, const std::string& pointer) const {
    if (!value.is_array()) fail(pointer, "expected an array, got " + describe(value));
    return value;
  }

  void only_keys(const json& object, const std::string& pointer, std::initializer_list<const char*> keys) const {
    if (!object.is_object()) fail(pointer, "expected an object, got " + describe(object));
    for (const auto& item : object.items()) {
      const std::string& key = item.key();
      if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return key == k; }) == keys.end()) {
        std::string known;
        for (const char* k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
        fail(pointer + "/" + key, "unknown key (expected one of: " + known + ")");
      }
    }
  }

 private:
  std::string file_;
};

// A point given either absolutely ("position") or as fractions of the scene's
// bounds ("position_in_bounds": [0.5, 0.1, 0.5] is the centre, near the floor),
// which keeps views right whatever units a model was authored in.
glm::vec3 read_point(const Reader& r, const json& j, const std::string& p, const SceneDescription& scene) {
  if (j.contains("position_in_bounds")) {
    const glm::vec3 f = r.vec3(j["position_in_bounds"], p + "/position_in_bounds", -10.0, 10.0);
    return scene.bounds.min + f * (scene.bounds.max - scene.bounds.min);
  }
  if (!j.contains("position")) r.fail(p + "/position", "is missing (or give position_in_bounds)");
  return r.vec3(j["position"], p + "/position");
}

SceneLight read_light(const Reader& r, const json& j, const std::string& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"type", "position", "position_in_bounds", "color", "intensity", "radius", "direction", "inner_cone_degrees",
                     "outer_cone_degrees"});
  SceneLight light;
  const std::string type = j.contains("type") ? r.string(j["type"], p + "/type") : "point";
  if (type == "spot") light.kind = LightKind::Spot;
  else if (type == "directional") light.kind = LightKind::Directional;
  else if (type != "point") r.fail(p + "/type", "expected \"point\", \"spot\" or \"directional\", got \"" + type + "\"");
  if (light.kind != LightKind::Directional) light.position = read_point(r, j, p, scene);
  if (j.contains("color")) light.color = r.color(j["color"], p + "/color");
  light.intensity = static_cast<float>(r.number(r.member(j, p, "intensity"), p + "/intensity", 1e-9, 1e9, "a positive number"));
  if (j.contains("radius")) light.radius = static_cast<float>(r.number(j["radius"], p + "/radius", 1e-6, 1e7, "a positive number"));
  if (light.kind != LightKind::Point) {
    const glm::vec3 direction = r.vec3(r.member(j, p, "direction"), p + "/direction");
    if (glm::length(direction) < 1e-6f) r.fail(p + "/direction", "expected a non-zero vector");
    light.direction = glm::normalize(direction);
  }
  if (light.kind == LightKind::Spot) {
    light.inner_cone = glm::radians(static_cast<float>(j.contains("inner_cone_degrees") ? r.number(j["inner_cone_degrees"], p + "/inner_cone_degrees", 0.0, 90.0, "degrees from 0 to 90") : 0.0));
    light.outer_cone = glm::radians(static_cast<float>(j.contains("outer_cone_degrees") ? r.number(j["outer_cone_degrees"], p + "/outer_cone_degrees", 0.0, 90.0, "degrees from 0 to 90") : 45.0));
    if (light.inner_cone > light.outer_cone) r.fail(p + "/inner_cone_degrees", "must not exceed outer_cone_degrees");
  }
  return light;
}

LightGenerator read_generator(const Reader& r, const json& j, const std::string& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"count", "seed", "box", "color", "intensity", "radius"});
  LightGenerator g;
  g.count = static_cast<std::uint32_t>(r.number(r.member(j, p, "count"), p + "/count", 0, kMaxLights,
                                                  ("a whole number from 0 to " + std::to_string(kMaxLights)).c_str()));
  if (j.contains("seed")) g.seed = static_cast<std::uint32_t>(r.number(j["seed"], p + "/seed", 0, 4294967295.0, "a whole number"));
  if (!j.contains("box") || (j["box"].is_string() && j["box"] == "bounds")) {
    g.box_min = scene.bounds.min;
    g.box_max = scene.bounds.max;
  } else {
    const json& box = j["box"];
    r.only_keys(box, p + "/box", {"min", "max", "min_in_bounds", "max_in_bounds"});
    auto corner = [&](const char* absolute, const char* relative) {
      if (box.contains(relative)) {
        return scene.bounds.min + r.vec3(box[relative], p + "/box/" + relative, -10.0, 10.0) * (scene.bounds.max - scene.bounds.min);
      }
      return r.vec3(r.member(box, p + "/box", absolute), p + "/box/" + absolute);
    };
    g.box_min = corner("min", "min_in_bounds");
    g.box_max = corner("max", "max_in_bounds");
    if (glm::any(glm::greaterThan(g.box_min, g.box_max))) r.fail(p + "/box", "expected min <= max in every axis");
  }
  if (j.contains("color") && !(j["color"].is_string() && j["color"] == "random")) g.color = r.color(j["color"], p + "/color");
  const glm::vec2 intensity = r.range(r.member(j, p, "intensity"), p + "/intensity", 1e-9, 1e9, "a positive number");
  g.intensity_min = intensity.x;
  g.intensity_max = intensity.y;
  if (j.contains("radius")) g.radius_range = r.range(j["radius"], p + "/radius", 1e-6, 1e7, "a positive number");
  return g;
}

NamedView read_view(const Reader& r, const json& j, const std::string& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"name", "position", "position_in_bounds", "yaw_degrees", "pitch_degrees"});
  NamedView view;
  view.name = r.string(r.member(j, p, "name"), p + "/name");
  view.position = read_point(r, j, p, scene);
  view.yaw_degrees = static_cast<float>(j.contains("yaw_degrees") ? r.number(j["yaw_degrees"], p + "/yaw_degrees", -720, 720, "degrees") : 0.0);
  view.pitch_degrees = static_cast<float>(j.contains("pitch_degrees") ? r.number(j["pitch_degrees"], p + "/pitch_degrees", -90, 90, "degrees from -90 to 90") : 0.0);
  return view;
}

// Places an imported model's instances and lights under a model transform.
void add_model(SceneDescription& scene, const ModelImport& model, const glm::mat4& placement) {
  for (SceneInstance instance : model.instances) {
    instance.asset = model.asset;
    // Placement scales are positive (checked when read), so this decomposes.
    const std::optional<Transform> placed = from_matrix(placement * to_matrix(instance.transform));
    if (!placed) continue;
    instance.transform = *placed;
    scene.instances.push_back(instance);
  }
  for (SceneLight light : model.lights) {
    light.position = glm::vec3(placement * glm::vec4(light.position, 1.0f));
    light.direction = glm::normalize(glm::vec3(placement * glm::vec4(light.direction, 0.0f)));
    scene.lights.push_back(light);
  }
  if (!model.bounds.empty) scene.bounds.add_box(placement, model.bounds.min, model.bounds.max);
}

void merge_report(LoadReport& report, const ModelImport& model) {
  report.warnings.insert(report.warnings.end(), model.warnings.begin(), model.warnings.end());
  report.timings.parse_seconds += model.timings.parse_seconds;
  report.timings.decode_seconds += model.timings.decode_seconds;
  report.images += model.images;
}

}  // namespace

// Each outside view looks at the centre from a direction with a part of at
// least a third along every axis (azimuth from +Z towards +X, elevation above
// the horizon), so a flat model in any axis plane is seen at 20 degrees or
// more, never edge-on; each stands as close as lets the whole box fit a
// 60-degree vertical field of view at 4:3 or wider, with a margin.
std::vector<NamedView> framing_views(const Box& bounds) {
  const glm::vec3 lo = bounds.min, hi = bounds.max;
  const glm::vec3 centre = 0.5f * (lo + hi);
  const glm::vec3 size = hi - lo;
  const float reach = std::max({size.x, size.y, size.z, 1e-6f});
  auto look_at = [&](const char* name, glm::vec3 from) {
    const glm::vec3 d = glm::normalize(centre - from);
    return NamedView{name, from, glm::degrees(std::atan2(d.x, -d.z)), glm::degrees(std::asin(glm::clamp(d.y, -1.0f, 1.0f)))};
  };
  const float tan_y = std::tan(glm::radians(30.0f)) * 0.9f, tan_x = tan_y * 4.0f / 3.0f;
  auto around = [&](const char* name, float azimuth_degrees, float elevation_degrees) {
    const float a = glm::radians(azimuth_degrees), e = glm::radians(elevation_degrees);
    const glm::vec3 back(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));  // centre to camera
    const glm::vec3 right = glm::normalize(glm::cross(-back, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, -back);
    float distance = 1e-6f * reach;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 r = glm::vec3((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z) - centre;
      const float towards = glm::dot(r, back);
      distance = std::max({distance, towards + std::abs(glm::dot(r, right)) / tan_x, towards + std::abs(glm::dot(r, up)) / tan_y});
    }
    return look_at(name, centre + distance * back);
  };
  // Inside a flat model there is nothing around the centre: stand off its
  // plane instead, looking back at it.
  const int thinnest = size.x <= size.y && size.x <= size.z ? 0 : size.y <= size.z ? 1 : 2;
  NamedView inside{"inside", centre, 0.0f, 0.0f};
  if (size[thinnest] < 0.02f * reach) {
    glm::vec3 offset(0.0f);
    offset[thinnest] = 0.35f * reach;
    offset[(thinnest + 1) % 3] = 0.2f * reach;
    inside = look_at("inside", centre + offset);
  }
  return {around("front", 25.0f, 30.0f), around("side", 65.0f, 25.0f), around("corner", 225.0f, 35.0f), around("top", 45.0f, 60.0f),
          inside};
}

std::string view_json(const NamedView& view) {
  char text[256];
  std::snprintf(text, sizeof text, "\"position\": [%.3f, %.3f, %.3f], \"yaw_degrees\": %.2f, \"pitch_degrees\": %.2f }",
                view.position.x, view.position.y, view.position.z, view.yaw_degrees, view.pitch_degrees);
  return "{ \"name\": " + json(view.name).dump() + ", " + text;
}

std::string camera_argument(const NamedView& view) {
  char text[160];
  std::snprintf(text, sizeof text, "%.3f,%.3f,%.3f,%.2f,%.2f", view.position.x, view.position.y, view.position.z, view.yaw_degrees,
                view.pitch_degrees);
  return text;
}

std::optional<NamedView> parse_camera_argument(std::string_view text) {
  std::array<float, 5> values{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::size_t comma = text.find(',', start);
    if ((comma == std::string_view::npos) != (i + 1 == values.size())) return std::nullopt;
    const std::string number(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    char* end = nullptr;
    values[i] = std::strtof(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(values[i])) return std::nullopt;
    start = comma + 1;
  }
  if (values[4] < -90.0f || values[4] > 90.0f) return std::nullopt;
  return NamedView{"camera", glm::vec3(values[0], values[1], values[2]), values[3], values[4]};
}

SceneDescription load_scene_file(const fs::path& path, AssetManager& assets, LoadReport& report,
                                 const ProgressCallback& progress) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw SceneFileError(file + ": cannot open the scene file");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for numbers beyond a double (1e400).
    std::string what = e.what();
    throw SceneFileError(file + ": not valid JSON (" + what.substr(what.find(']') + 2) + ")");
  }
  const Reader r(file);
  r.only_keys(root, "", {"name", "models", "lights", "light_generators", "views", "ambient", "background", "exposure", "default_mode", "systems"});
  SceneDescription scene;
  scene.name = root.contains("name") ? r.string(root["name"], "/name") : path.stem().string();
  // The mode name is checked against the technique table by the World.
  if (root.contains("default_mode")) scene.default_mode = r.string(root["default_mode"], "/default_mode");

  std::map<std::string, ModelImport> imported;  // canonical path -> import, so repeats share one asset
  std::optional<ModelImport> builtin;
  std::vector<NamedView> builtin_views;
  if (root.contains("models")) {
    const json& models = r.array(root["models"], "/models");
    for (std::size_t i = 0; i < models.size(); ++i) {
      const std::string p = "/models/" + std::to_string(i);
      const json& m = models[i];
      r.only_keys(m, p, {"path", "builtin", "position", "rotation_degrees", "scale", "fetch", "materials"});
      glm::mat4 placement(1.0f);
      if (m.contains("position")) placement = glm::translate(placement, r.vec3(m["position"], p + "/position"));
      if (m.contains("rotation_degrees")) placement *= glm::mat4_cast(glm::quat(glm::radians(r.vec3(m["rotation_degrees"], p + "/rotation_degrees"))));
      if (m.contains("scale")) {
        const glm::vec3 scale = m["scale"].is_number() ? glm::vec3(static_cast<float>(r.number(m["scale"], p + "/scale", 1e-6, 1e6, "a positive number")))
                                                       : r.vec3(m["scale"], p + "/scale", 1e-6, 1e6);
        placement = glm::scale(placement, scale);
      }
      if (m.contains("builtin")) {
        // The procedural courtyard as a model: its geometry and views; lights come from this file.
        if (r.string(m["builtin"], p + "/builtin") != kBuiltinSceneName) {
          r.fail(p + "/builtin", std::string("expected \"") + kBuiltinSceneName + "\"");
        }
        // Built once: every copy places the same asset, so copies draw instanced.
        if (!builtin) {
          const SceneDescription courtyard = build_builtin_scene(assets, 0u);
          builtin.emplace();
          builtin->asset = courtyard.instances.empty() ? MeshAssetHandle{} : courtyard.instances.front().asset;
          builtin->instances = courtyard.instances;
          builtin->bounds = courtyard.instances.empty() ? Box{} : courtyard.bounds;
          builtin_views = courtyard.views;
          scene.exposure = courtyard.exposure;
          scene.background = courtyard.background;
        }
        add_model(scene, *builtin, placement);
        // Its views are in its own frame: they hold for a copy left where it was built.
        if (scene.views.empty() && placement == glm::mat4(1.0f)) scene.views = builtin_views;
        continue;
      }
      const fs::path model_path = (path.parent_path() / r.string(r.member(m, p, "path"), p + "/path")).lexically_normal();
      std::error_code ec;
      if (!fs::is_regular_file(model_path, ec)) {
        const std::string fetch = m.contains("fetch") ? "; fetch it with `" + r.string(m["fetch"], p + "/fetch") + "`" : "";
        r.fail(p + "/path", model_path.string() + " does not exist" + fetch);
      }
      const std::string key = fs::weakly_canonical(model_path).string();
      if (!imported.contains(key)) {
        ImportOptions options;
        options.progress = progress;
        if (m.contains("materials")) {
          const std::string name = r.string(m["materials"], p + "/materials");
          options.convention = material_convention(name);
          if (!options.convention) r.fail(p + "/materials", "expected \"gltf\", \"bistro\" or \"phong\", got \"" + name + "\"");
        }
        imported.emplace(key, import_model(model_path, assets, options));
        merge_report(report, imported.at(key));
      }
      add_model(scene, imported.at(key), placement);
    }
  }
  // After the models: the file's settings win over a built-in model's.
  if (root.contains("ambient")) scene.ambient = r.color(root["ambient"], "/ambient");
  if (root.contains("background")) scene.background = r.color(root["background"], "/background");
  if (root.contains("exposure")) scene.exposure = static_cast<float>(r.number(root["exposure"], "/exposure", 1e-6, 1e6, "a positive number"));
  if (root.contains("systems")) {
    // Settings of optional systems by name; each system clamps its own.
    if (!root["systems"].is_object()) r.fail("/systems", "expected an object of numbers by system name, got " + r.describe(root["systems"]));
    for (const auto& [name, value] : root["systems"].items()) {
      scene.system_options[name] = r.number(value, "/systems/" + name, -1e9, 1e9, "a number");
    }
  }
  if (root.contains("lights")) {
    const json& lights = r.array(root["lights"], "/lights");
    for (std::size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(read_light(r, lights[i], "/lights/" + std::to_string(i), scene));
  }
  if (root.contains("light_generators")) {
    const json& generators = r.array(root["light_generators"], "/light_generators");
    for (std::size_t i = 0; i < generators.size(); ++i) {
      const LightGenerator g = read_generator(r, generators[i], "/light_generators/" + std::to_string(i), scene);
      for (const SceneLight& light : generate_lights(g)) scene.lights.push_back(light);
      if (!scene.fill_generator) scene.fill_generator = g;
    }
  }
  if (root.contains("views")) {
    const json& views = r.array(root["views"], "/views");
    if (views.empty() || views.size() > 9) r.fail("/views", "expected 1 to 9 views, got " + std::to_string(views.size()));
    scene.views.clear();
    for (std::size_t i = 0; i < views.size(); ++i) scene.views.push_back(read_view(r, views[i], "/views/" + std::to_string(i), scene));
  } else if (scene.views.empty()) {
    scene.views = framing_views(scene.bounds);
  }
  return scene;
}

SceneDescription load_model_scene(const fs::path& path, AssetManager& assets, std::uint32_t extra_lights, LoadReport& report,
                                  const ProgressCallback& progress) {
  ImportOptions options;
  options.progress = progress;
  const ModelImport model = import_model(path, assets, options);
  merge_report(report, model);
  SceneDescription scene;
  scene.name = path.stem().string();
  add_model(scene, model, glm::mat4(1.0f));
  scene.views = framing_views(scene.bounds);
  resize_lights(scene, static_cast<std::uint32_t>(scene.lights.size()) + extra_lights);
  return scene;
}

}  // namespace atrium::assets
