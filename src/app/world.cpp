#include "app/world.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/constants.hpp>
#include <glm/gtx/quaternion.hpp>

#include "app/progress_bar.hpp"
#include "base/golden_angle.hpp"
#include "assets/asset_manager.hpp"
#include "assets/file_lookup.hpp"
#include "assets/scene_file.hpp"
#include "assets/builtin_scene.hpp"
#include "gfx/gl_features.hpp"
#include "render/gpu_assets.hpp"
#include "components/camera.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/mesh_instance.hpp"
#include "components/system_options.hpp"
#include "render/frame/frame_modules.hpp"
#include "components/bounds.hpp"
#include "systems/bounds.hpp"
#include "systems/camera.hpp"
#include "systems/fireflies/fireflies.hpp"
#include "render/post/bloom/bloom.hpp"
#include "systems/frustum_culling.hpp"
#include "render/light_buffer.hpp"
#include "systems/light_radius.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

// The scene file's "lighting_stage" (checked when it loaded), else auto.
LightingStage scene_lighting_stage(const assets::SceneDescription& scene) {
  const auto& names = kLightingStageNames;
  const auto found = std::find(names.begin(), names.end(), scene.lighting_stage);
  return found == names.end() ? LightingStage::Automatic : static_cast<LightingStage>(found - names.begin());
}

assets::SceneDescription load_scene(const WorldOptions& options, assets::AssetManager& assets, assets::LoadReport& report) {
  ProgressBar bar(std::filesystem::path(options.scene).filename().string());
  const assets::ProgressCallback progress = [&](std::string_view stage, std::size_t done, std::size_t total) {
    bar.update(stage, done, total);
  };
  if (options.scene == assets::kBuiltinSceneName) {
    // Generating the courtyard and its textures is its "parse" time.
    const auto start = std::chrono::steady_clock::now();
    assets::SceneDescription scene = assets::build_builtin_scene(assets, options.lights);
    report.timings.parse_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return scene;
  }
  const std::string extension = assets::lowercase_extension(options.scene);
  try {
    if (assets::is_model_file(options.scene)) {
      return assets::load_model_scene(options.scene, assets, options.lights.value_or(0), report, progress);
    }
    if (extension == ".json") {
      assets::SceneDescription scene = assets::load_scene_file(options.scene, assets, report, progress);
      if (!techniques::find_technique(scene.default_mode)) {
        throw InputError(options.scene + ": /default_mode: unknown mode '" + scene.default_mode + "' (modes: " +
                         techniques::technique_names() + ")");
      }
      if (!scene.lighting_stage.empty() && std::find(kLightingStageNames.begin(), kLightingStageNames.end(),
                                                     scene.lighting_stage) == kLightingStageNames.end()) {
        throw InputError(options.scene + ": /lighting_stage: unknown lighting stage '" + scene.lighting_stage + "' (stages: auto, fragment, compute)");
      }
      if (options.lights) assets::resize_lights(scene, *options.lights);
      return scene;
    }
  } catch (const assets::SceneFileError& e) {
    throw InputError(e.what());
  } catch (const assets::ImportError& e) {
    throw InputError(e.what());
  }
  throw InputError(options.scene + ": unknown scene (expected the built-in scene '" + std::string(assets::kBuiltinSceneName) +
                   "', a scene file .json, or a model: " + assets::model_formats_text() + ")");
}

void spawn_lights(ecs::Registry& registry, const assets::SceneDescription& scene, std::optional<float> radius) {
  // Animated lights start at different points of their circles, spread by the
  // golden angle so that neighbours do not move in step.
  std::uint32_t animated = 0;
  for (const auto& light : scene.lights) {
    const ecs::Entity e = registry.create();
    Transform transform{light.position};
    // Lights point along their local -Z, like glTF's.
    const glm::vec3 forward(0.0f, 0.0f, -1.0f);
    if (glm::dot(forward, light.direction) < -0.9999f) transform.rotation = glm::angleAxis(glm::pi<float>(), glm::vec3(0, 1, 0));
    else transform.rotation = glm::rotation(forward, glm::normalize(light.direction));
    registry.add<Transform>(e, transform);
    const bool directional = light.kind == assets::LightKind::Directional;
    registry.add<LightColor>(e, light.color, light.intensity);
    if (light.radius) registry.add<LightRadius>(e, *light.radius);
    if (light.kind == assets::LightKind::Spot) registry.add<SpotCone>(e, light.inner_cone, light.outer_cone);
    if (directional) registry.add<DirectionalLight>(e);
    if (radius) set_light_radius(registry, e, *radius);
    if (light.generated && light.kind == assets::LightKind::Point) {
      registry.add<LightAnimation>(e, light.position, golden_angle_phase(animated++));
    }
  }
}

void spawn(ecs::Registry& registry, const assets::SceneDescription& scene, std::optional<float> light_radius) {
  for (const auto& instance : scene.instances) {
    const ecs::Entity e = registry.create();
    registry.add<Transform>(e, instance.transform);
    registry.add<MeshInstance>(e, instance.asset, instance.mesh);
  }
  spawn_lights(registry, scene, light_radius);
  const ecs::Entity camera = registry.create();
  registry.add<Transform>(camera);
  registry.add<Camera>(camera);
  registry.add<CameraAngles>(camera);
  registry.add<FlyCamera>(camera);
}

}  // namespace

void require_known_mode(const std::string& mode) {
  if (techniques::find_technique(mode)) return;
  throw InputError("unknown mode '" + mode + "' (modes: " + techniques::technique_names() + ")");
}

World::World(const WorldOptions& options) {
  scene_ = load_scene(options, registry_.set_resource<assets::AssetManager>(), report_);
  for (const std::string& warning : report_.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  start(options);
}

World::World(assets::AssetManager assets, assets::SceneDescription scene, const WorldOptions& options)
    : scene_(std::move(scene)) {
  registry_.set_resource<assets::AssetManager>(std::move(assets));
  start(options);
}

void World::start(const WorldOptions& options) {
  if (options.camera) scene_.views = {*options.camera};
  const auto upload_start = std::chrono::steady_clock::now();
  auto& gpu = registry_.set_resource<render::GpuAssets>(options.max_texture_size);
  for (std::string& warning : gpu.upload(registry_.resource<assets::AssetManager>())) {
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
    report_.warnings.push_back(std::move(warning));
  }
  upload_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - upload_start).count();

  registry_.set_resource<Viewport>(Viewport{options.size});
  registry_.set_resource<ViewState>();
  registry_.set_resource<SceneSettings>(SceneSettings{scene_.ambient, scene_.background, scene_.exposure});
  registry_.set_resource<SceneBounds>(SceneBounds{scene_.bounds});
  registry_.set_resource<RendererSettings>();
  registry_.set_resource<LightAnimationSettings>();
  auto& system_options = registry_.set_resource<SystemOptions>();
  for (const auto& [name, value] : scene_.system_options) system_options.set(name, value);
  registry_.set_resource<render::FrameModules>();
  registry_.set_resource<render::MeshRenderer>(registry_.resource<render::GpuAssets>());
  light_radius_ = options.light_radius;
  spawn(registry_, scene_, light_radius_);

  apply_settings(options);
  set_view(options.view);

  register_bounds(scheduler_);
  register_camera(scheduler_);
  register_frustum_culling(scheduler_);
  register_fireflies(scheduler_, registry_);
  render::register_bloom(registry_);
  render::register_light_buffer(scheduler_);
  render::register_mesh_renderer(scheduler_);
}

void World::apply_settings(const WorldOptions& options) {
  set_mode(options.mode.value_or(scene_.default_mode));
  auto& settings = registry_.resource<RendererSettings>();
  settings.shading = options.shading;
  settings.debug_view = options.debug_view;
  settings.technique_options = options.technique_options;
  settings.technique_options.lighting_stage = options.lighting_stage.value_or(scene_lighting_stage(scene_));
  if (const gfx::GlFeatures& gl = gfx::gl_features(); !gl.full_tier() && !settings.technique_options.compute_free) {
    settings.technique_options.compute_free = true;
    if (!compute_free_noted_) {
      std::fprintf(stderr, "note: %s has %s: running on the compute-free tier\n", gl.api_name().c_str(),
                   gl.missing_for_full_tier().c_str());
      compute_free_noted_ = true;
    }
  }
  // With compute shaders the light animation moves point lights on the GPU.
  registry_.resource<LightAnimationSettings>().on_gpu = !settings.technique_options.compute_free;
  settings.frustum_culling = options.frustum_culling;
  settings.occlusion_culling = options.occlusion_culling;
  settings.culling_device = options.culling_device;
  settings.poison_targets = options.poison_targets;
  settings.shadows = options.shadows;
  auto& system_options = registry_.resource<SystemOptions>();
  for (const auto& [name, value] : options.system_options) system_options.set(name, value);
}

void World::frame(double delta_seconds) { scheduler_.run_frame(registry_, delta_seconds); }

void World::set_view(int index) {
  if (index < 1 || index > static_cast<int>(scene_.views.size())) {
    throw InputError("view " + std::to_string(index) + " does not exist (the scene has views 1.." +
                     std::to_string(scene_.views.size()) + ")");
  }
  view_ = index;
  apply_view(registry_, scene_.views[static_cast<std::size_t>(index - 1)]);
}

void World::set_mode(const std::string& mode) {
  require_known_mode(mode);
  registry_.resource<RendererSettings>().mode = mode;
}

void World::set_size(glm::ivec2 size) { registry_.resource<Viewport>().size = size; }

void World::set_light_count(std::uint32_t count) {
  std::vector<ecs::Entity> lights;
  registry_.view<LightColor>().each([&](ecs::Entity e, const LightColor&) { lights.push_back(e); });
  for (const ecs::Entity e : lights) registry_.destroy(e);
  assets::resize_lights(scene_, count);
  spawn_lights(registry_, scene_, light_radius_);
}

void World::set_light_radius(std::optional<float> radius) {
  light_radius_ = radius;
  set_light_count(light_count());
}

std::uint32_t World::light_count() const { return static_cast<std::uint32_t>(scene_.lights.size()); }

std::vector<std::string> World::reload_shaders() {
  std::vector<std::string> errors = registry_.resource<render::GpuAssets>().shaders().reload();
  // Programs that were replaced lost the uniforms their technique set once.
  registry_.resource<render::MeshRenderer>().recreate_technique();
  return errors;
}

const std::string& World::mode() const {
  return registry_.resource<RendererSettings>().mode;
}

std::vector<std::string> World::modes() const {
  return techniques::mode_names(registry_.resource<RendererSettings>().technique_options);
}

void require_offered_view(World& world, const std::string& view) {
  if (view.empty() || world.renderer().offers(view)) return;
  throw render::UnknownViewError("mode " + world.mode() + " does not offer the debug view '" + view +
                                 "' (its views: " + render::view_names(world.renderer().offered_views()) + ")");
}

}  // namespace atrium
