#include "app/world.hpp"

#include "assets/asset_manager.hpp"
#include "assets/builtin_scene.hpp"
#include "assets/gpu_assets.hpp"
#include "components/camera.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/mesh_instance.hpp"
#include "systems/camera.hpp"
#include "systems/light_buffer.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium {
namespace {

assets::SceneDescription load_scene(const WorldOptions& options, assets::AssetManager& assets) {
  if (options.scene == assets::kBuiltinSceneName) return assets::build_builtin_scene(assets, options.lights);
  throw InputError(options.scene + ": unknown scene; this build knows the built-in scene '" +
                   std::string(assets::kBuiltinSceneName) + "' (scene files and glTF models are not supported yet)");
}

void spawn(ecs::Registry& registry, const assets::SceneDescription& scene) {
  for (const auto& instance : scene.instances) {
    const ecs::Entity e = registry.create();
    registry.add<Transform>(e, instance.transform);
    registry.add<MeshInstance>(e, instance.asset, instance.mesh);
  }
  for (const auto& light : scene.lights) {
    const ecs::Entity e = registry.create();
    registry.add<Transform>(e, Transform{light.position});
    registry.add<LightColor>(e, light.color, light.intensity);
    if (light.radius) registry.add<LightRadius>(e, *light.radius);
  }
  const ecs::Entity camera = registry.create();
  registry.add<Transform>(camera);
  registry.add<Camera>(camera);
  registry.add<CameraAngles>(camera);
}

}  // namespace

void require_known_mode(const std::string& mode) {
  if (lighting::find_technique(mode)) return;
  std::string known;
  for (const auto& info : lighting::technique_table()) known += (known.empty() ? "" : ", ") + std::string(info.name);
  throw InputError("unknown mode '" + mode + "' (modes: " + known + ")");
}

World::World(const WorldOptions& options) {
  scene_ = load_scene(options, registry_.set_resource<assets::AssetManager>());
  start(options);
}

World::World(assets::AssetManager assets, assets::SceneDescription scene, const WorldOptions& options)
    : scene_(std::move(scene)) {
  registry_.set_resource<assets::AssetManager>(std::move(assets));
  start(options);
}

void World::start(const WorldOptions& options) {
  registry_.set_resource<assets::GpuAssets>().upload(registry_.resource<assets::AssetManager>());

  registry_.set_resource<Viewport>(Viewport{options.size});
  registry_.set_resource<ViewState>();
  registry_.set_resource<SceneSettings>(SceneSettings{scene_.ambient, scene_.background, scene_.exposure});
  registry_.set_resource<RendererSettings>();
  registry_.set_resource<MeshRenderer>();
  spawn(registry_, scene_);

  set_mode(options.mode.value_or(scene_.default_mode));
  set_view(options.view);

  register_camera(scheduler_);
  register_light_buffer(scheduler_);
  register_mesh_renderer(scheduler_);
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

const std::string& World::mode() const {
  return registry_.resource<RendererSettings>().mode;
}

}  // namespace atrium
