#include "assets/scene_file.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "assets/builtin_scene.hpp"
#include "assets/json_reader.hpp"
#include "components/light.hpp"


namespace atrium::assets {
namespace {

namespace fs = std::filesystem;

// Scene-specific values on top of the JsonReader: points, colours and ranges.
class Reader : public JsonReader {
 public:
  using JsonReader::JsonReader;

  glm::vec3 vec3(const Json& value, const JsonPointer& at, double min = -1e7, double max = 1e7) const {
    const std::array<double, 3> v = numbers<3>(value, at, min, max);
    return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  }

  // A colour: [r, g, b] with non-negative channels, or one number for grey.
  glm::vec3 color(const Json& value, const JsonPointer& at) const {
    if (value.is_number()) return glm::vec3(static_cast<float>(number(value, at, 0.0, 1e6, "a non-negative number")));
    return vec3(value, at, 0.0, 1e6);
  }

  // One number, or [min, max].
  glm::vec2 range(const Json& value, const JsonPointer& at, double min, double max, std::string_view expected) const {
    if (value.is_number()) return glm::vec2(static_cast<float>(number(value, at, min, max, expected)));
    if (!value.is_array() || value.size() != 2) fail(at, std::string("expected ") + std::string(expected) + " or [min, max], got " + describe(value));
    const glm::vec2 r(static_cast<float>(number(value[0], at / 0, min, max, expected)), static_cast<float>(number(value[1], at / 1, min, max, expected)));
    if (r.x > r.y) fail(at, "expected [min, max] with min <= max, got " + describe(value));
    return r;
  }
};

// A point given either absolutely ("position") or as fractions of the scene's
// bounds ("position_in_bounds": [0.5, 0.1, 0.5] is the centre, near the floor),
// which keeps views right whatever units a model was authored in.
glm::vec3 read_point(const Reader& r, const Json& j, const JsonPointer& p, const SceneDescription& scene) {
  if (const Json* f = r.find(j, "position_in_bounds")) {
    return scene.bounds.min + r.vec3(*f, p / "position_in_bounds", -10.0, 10.0) * (scene.bounds.max - scene.bounds.min);
  }
  if (!r.find(j, "position")) r.fail(p / "position", "is missing (or give position_in_bounds)");
  return r.vec3(j["position"], p / "position");
}

SceneLight read_light(const Reader& r, const Json& j, const JsonPointer& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"type", "position", "position_in_bounds", "color", "intensity", "radius", "direction", "inner_cone_degrees",
                     "outer_cone_degrees"});
  SceneLight light;
  const std::string type = r.string_or(j, p, "type", "point");
  if (type == "spot") light.kind = LightKind::Spot;
  else if (type == "directional") light.kind = LightKind::Directional;
  else if (type != "point") r.fail(p / "type", "expected \"point\", \"spot\" or \"directional\", got \"" + type + "\"");
  if (light.kind != LightKind::Directional) light.position = read_point(r, j, p, scene);
  if (const Json* color = r.find(j, "color")) light.color = r.color(*color, p / "color");
  light.intensity = static_cast<float>(r.number(r.required(j, p, "intensity"), p / "intensity", 1e-9, 1e9, "a positive number"));
  if (const Json* radius = r.find(j, "radius")) light.radius = static_cast<float>(r.number(*radius, p / "radius", 1e-6, 1e7, "a positive number"));
  if (light.kind != LightKind::Point) {
    const glm::vec3 direction = r.vec3(r.required(j, p, "direction"), p / "direction");
    if (glm::length(direction) < 1e-6f) r.fail(p / "direction", "expected a non-zero vector");
    light.direction = glm::normalize(direction);
  }
  if (light.kind == LightKind::Spot) {
    light.inner_cone = glm::radians(static_cast<float>(r.number_or(j, p, "inner_cone_degrees", 0.0, 0.0, 90.0, "degrees from 0 to 90")));
    light.outer_cone = glm::radians(static_cast<float>(r.number_or(j, p, "outer_cone_degrees", 45.0, 0.0, 90.0, "degrees from 0 to 90")));
    if (light.inner_cone > light.outer_cone) r.fail(p / "inner_cone_degrees", "must not exceed outer_cone_degrees");
  }
  return light;
}

LightGenerator read_generator(const Reader& r, const Json& j, const JsonPointer& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"count", "seed", "box", "color", "intensity", "radius"});
  LightGenerator g;
  g.count = static_cast<std::uint32_t>(r.whole(r.required(j, p, "count"), p / "count", 0, kMaxLights));
  g.seed = static_cast<std::uint32_t>(r.whole_or(j, p, "seed", 0, 4294967295u, g.seed));
  const Json* box = r.find(j, "box");
  if (!box || *box == "bounds") {
    g.box_min = scene.bounds.min;
    g.box_max = scene.bounds.max;
  } else {
    const JsonPointer bp = p / "box";
    r.only_keys(*box, bp, {"min", "max", "min_in_bounds", "max_in_bounds"});
    auto corner = [&](const char* absolute, const char* relative) {
      if (const Json* f = r.find(*box, relative)) {
        return scene.bounds.min + r.vec3(*f, bp / relative, -10.0, 10.0) * (scene.bounds.max - scene.bounds.min);
      }
      return r.vec3(r.required(*box, bp, absolute), bp / absolute);
    };
    g.box_min = corner("min", "min_in_bounds");
    g.box_max = corner("max", "max_in_bounds");
    if (glm::any(glm::greaterThan(g.box_min, g.box_max))) r.fail(bp, "expected min <= max in every axis");
  }
  if (const Json* color = r.find(j, "color"); color && *color != "random") g.color = r.color(*color, p / "color");
  const glm::vec2 intensity = r.range(r.required(j, p, "intensity"), p / "intensity", 1e-9, 1e9, "a positive number");
  g.intensity_min = intensity.x;
  g.intensity_max = intensity.y;
  if (const Json* radius = r.find(j, "radius")) g.radius_range = r.range(*radius, p / "radius", 1e-6, 1e7, "a positive number");
  return g;
}

NamedView read_view(const Reader& r, const Json& j, const JsonPointer& p, const SceneDescription& scene) {
  r.only_keys(j, p, {"name", "position", "position_in_bounds", "yaw_degrees", "pitch_degrees"});
  NamedView view;
  view.name = r.string(r.required(j, p, "name"), p / "name");
  view.position = read_point(r, j, p, scene);
  view.yaw_degrees = static_cast<float>(r.number_or(j, p, "yaw_degrees", 0.0, -720, 720, "degrees from -720 to 720"));
  view.pitch_degrees = static_cast<float>(r.number_or(j, p, "pitch_degrees", 0.0, -90, 90, "degrees from -90 to 90"));
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

// The whole scene file, its models imported.
SceneDescription read_scene(const Reader& r, const Json& root, const fs::path& path, AssetManager& assets, LoadReport& report,
                            const ProgressCallback& progress) {
  const JsonPointer top;
  r.only_keys(root, top, {"name", "models", "lights", "light_generators", "views", "ambient", "background", "exposure", "default_mode",
                          "lighting_stage", "systems"});
  SceneDescription scene;
  scene.name = r.string_or(root, top, "name", path.stem().string());
  // The mode name is checked against the technique table by the World.
  scene.default_mode = r.string_or(root, top, "default_mode", scene.default_mode);
  scene.lighting_stage = r.string_or(root, top, "lighting_stage", scene.lighting_stage);

  std::map<std::string, ModelImport> imported;  // canonical path -> import, so repeats share one asset
  std::optional<ModelImport> builtin;
  std::vector<NamedView> builtin_views;
  if (const Json* models_json = r.find(root, "models")) {
    const Json& models = r.array(*models_json, top / "models");
    for (std::size_t i = 0; i < models.size(); ++i) {
      const JsonPointer p = top / "models" / i;
      const Json& m = models[i];
      r.only_keys(m, p, {"path", "builtin", "position", "rotation_degrees", "scale", "fetch", "materials"});
      glm::mat4 placement(1.0f);
      if (const Json* position = r.find(m, "position")) placement = glm::translate(placement, r.vec3(*position, p / "position"));
      if (const Json* rotation = r.find(m, "rotation_degrees")) placement *= glm::mat4_cast(glm::quat(glm::radians(r.vec3(*rotation, p / "rotation_degrees"))));
      if (const Json* scale_json = r.find(m, "scale")) {
        const glm::vec3 scale = scale_json->is_number() ? glm::vec3(static_cast<float>(r.number(*scale_json, p / "scale", 1e-6, 1e6, "a positive number")))
                                                        : r.vec3(*scale_json, p / "scale", 1e-6, 1e6);
        placement = glm::scale(placement, scale);
      }
      if (const Json* builtin_json = r.find(m, "builtin")) {
        // The procedural courtyard as a model: its geometry and views; lights come from this file.
        if (const std::string name = r.string(*builtin_json, p / "builtin"); name != kBuiltinSceneName) {
          r.fail(p / "builtin", std::string("expected \"") + kBuiltinSceneName + "\", got \"" + name + "\"");
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
      const fs::path model_path = (path.parent_path() / r.string(r.required(m, p, "path"), p / "path")).lexically_normal();
      std::error_code ec;
      if (!fs::is_regular_file(model_path, ec)) {
        const Json* fetch = r.find(m, "fetch");
        r.fail(p / "path", model_path.string() + " does not exist" + (fetch ? "; fetch it with `" + r.string(*fetch, p / "fetch") + "`" : ""));
      }
      const std::string key = fs::weakly_canonical(model_path).string();
      if (!imported.contains(key)) {
        ImportOptions options;
        options.progress = progress;
        if (const Json* materials = r.find(m, "materials")) {
          const std::string name = r.string(*materials, p / "materials");
          options.convention = material_convention(name);
          if (!options.convention) r.fail(p / "materials", "expected \"gltf\", \"bistro\" or \"phong\", got \"" + name + "\"");
        }
        imported.emplace(key, import_model(model_path, assets, options));
        merge_report(report, imported.at(key));
      }
      add_model(scene, imported.at(key), placement);
    }
  }
  // After the models: the file's settings win over a built-in model's.
  if (const Json* ambient = r.find(root, "ambient")) scene.ambient = r.color(*ambient, top / "ambient");
  if (const Json* background = r.find(root, "background")) scene.background = r.color(*background, top / "background");
  scene.exposure = static_cast<float>(r.number_or(root, top, "exposure", scene.exposure, 1e-6, 1e6, "a positive number"));
  // Settings of optional systems by name; each system clamps its own.
  for (const auto& [name, value] : r.object_or_empty(root, top, "systems").items()) {
    scene.system_options[name] = r.number(value, top / "systems" / name, -1e9, 1e9, "a number");
  }
  const Json& lights = r.array_or_empty(root, top, "lights");
  for (std::size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(read_light(r, lights[i], top / "lights" / i, scene));
  const Json& generators = r.array_or_empty(root, top, "light_generators");
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const LightGenerator g = read_generator(r, generators[i], top / "light_generators" / i, scene);
    for (const SceneLight& light : generate_lights(g)) scene.lights.push_back(light);
    if (!scene.fill_generator) scene.fill_generator = g;
  }
  if (const Json* views_json = r.find(root, "views")) {
    const Json& views = r.array(*views_json, top / "views");
    if (views.empty() || views.size() > 9) r.fail(top / "views", "expected 1 to 9 views, got " + std::to_string(views.size()));
    scene.views.clear();
    for (std::size_t i = 0; i < views.size(); ++i) scene.views.push_back(read_view(r, views[i], top / "views" / i, scene));
  } else if (scene.views.empty()) {
    scene.views = framing_views(scene.bounds);
  }
  return scene;
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
  return "{ \"name\": " + Json(view.name).dump() + ", " + text;
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
  const Reader r(path.string());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneFileError(r.file() + ": cannot open the scene file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return read_scene(r, r.parse(text), path, assets, report, progress);
  } catch (const JsonError& e) {
    throw SceneFileError(e.what());
  }
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
