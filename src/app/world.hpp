// A World is one running scene: the registry with its entities and resources,
// the scheduler with every system registered in its phase, and the loaded
// assets. Both the window and the headless commands drive a World.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "assets/asset_manager.hpp"
#include "assets/scene.hpp"
#include "assets/scene_file.hpp"
#include "ecs/scheduler.hpp"
#include "components/technique_options.hpp"
#include "render/mesh_renderer.hpp"

namespace atrium {

// Bad user input (unknown scene, view or mode): the CLI exits 2 with the message.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct WorldOptions {
  std::string scene = "atrium";
  std::optional<std::uint32_t> lights;  // replaces the scene's light count
  std::optional<std::string> mode;      // the scene's default mode when absent
  int view = 1;                         // 1-based index into the scene's views
  glm::ivec2 size{1280, 720};
  std::string shading = "pbr";          // a name from render/lighting/shading_model.hpp
  std::string debug_view;               // empty, or a name from render/debug/debug_views.hpp
  TechniqueOptions technique_options;
  // Every point and spot light gets this radius, and the intensity whose derived
  // radius it is (so brightness stays sane); absent: the scene's own.
  std::optional<float> light_radius;
  // The widest and tallest texture uploaded (larger ones are downscaled); 0:
  // what the context allows.
  int max_texture_size = 0;
  // --camera: this one view replaces the scene's views.
  std::optional<assets::NamedView> camera;
  // --no-culling: every pass draws the whole scene.
  bool frustum_culling = true;
  // --shadows K: shadow maps for the K lights that matter most (0: off).
  int shadows = 0;
  // --no-occlusion-culling turns it off: passes draw what is in view, hidden or not.
  bool occlusion_culling = true;
  // --culling: where it tests (render/culling/): CPU or GPU, chosen per driver by default.
  CullingDevice culling_device = CullingDevice::Automatic;
  // --poison-targets: each target is marked before the pass that writes it
  // first (render/frame_graph.hpp), so that texels left unwritten show.
  bool poison_targets = false;
  // --lighting-stage: where full-screen passes run; absent: the scene file's
  // "lighting_stage", else auto (components/technique_options.hpp).
  std::optional<LightingStage> lighting_stage;
  // Settings of optional systems by name (components/system_options.hpp),
  // over the scene file's.
  std::map<std::string, double> system_options;
};

class World {
 public:
  // Loads the scene named in options and uploads it to the current GL context.
  explicit World(const WorldOptions& options);
  // A scene built elsewhere (tests, importers): `assets` holds what it references.
  World(assets::AssetManager assets, assets::SceneDescription scene, const WorldOptions& options);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Runs every phase once.
  void frame(double delta_seconds);

  // Moves the camera to stored view `index` (1-based). Throws InputError.
  void set_view(int index);
  void set_mode(const std::string& mode);
  // The settings a running world can change without loading its scene again:
  // mode, shading, debug view, technique options, culling, shadows and the
  // options of systems (what the page's panel sets; the scene, lights, view,
  // size and camera have calls of their own).
  void apply_settings(const WorldOptions& options);
  void set_size(glm::ivec2 size);
  // Replaces the light entities with the scene's first `count` lights
  // (assets::resize_lights: generated lights fill up, growing keeps the rest).
  void set_light_count(std::uint32_t count);
  [[nodiscard]] std::uint32_t light_count() const;
  // Respawns the lights with one radius for all (WorldOptions::light_radius) or
  // their own (nullopt).
  void set_light_radius(std::optional<float> radius);
  [[nodiscard]] std::optional<float> light_radius() const { return light_radius_; }
  // Recompiles every shader; a failing program keeps its old version and its
  // error comes back (one string per failing program).
  std::vector<std::string> reload_shaders();

  [[nodiscard]] ecs::Registry& registry() { return registry_; }
  // For systems beyond the core ones (the window adds input, fly camera, light
  // animation and overlay).
  [[nodiscard]] ecs::Scheduler& scheduler() { return scheduler_; }
  [[nodiscard]] const assets::SceneDescription& scene() const { return scene_; }
  [[nodiscard]] render::MeshRenderer& renderer() { return registry_.resource<render::MeshRenderer>(); }
  [[nodiscard]] const std::string& mode() const;
  // The modes this world runs with its tier and options (techniques::refusal
  // leaves out those that need compute on the compute-free tier, or refuse
  // MSAA while it is on), in table order: what `t`, menus and sweeps offer.
  [[nodiscard]] std::vector<std::string> modes() const;
  [[nodiscard]] int view() const { return view_; }
  // What loading reported: warnings, parse and decode times, images.
  [[nodiscard]] const assets::LoadReport& load_report() const { return report_; }
  [[nodiscard]] double upload_seconds() const { return upload_seconds_; }

 private:
  ecs::Registry registry_;
  ecs::Scheduler scheduler_;
  assets::SceneDescription scene_;
  int view_ = 1;
  std::optional<float> light_radius_;
  assets::LoadReport report_;
  double upload_seconds_ = 0.0;
  bool compute_free_noted_ = false;

  void start(const WorldOptions& options);
};

// Checks a mode name against the technique table; throws InputError listing the modes.
void require_known_mode(const std::string& mode);

// After a frame: a debug view asked for by name on the command line that this
// mode's frame does not offer (a view of another mode, msaa-edges without
// MSAA) would draw flat grey without a word, so it is refused,
// render::UnknownViewError (exit 2) naming the mode and the views it offers.
// The window's keys may still switch to a mode without the view: grey there.
void require_offered_view(World& world, const std::string& view);

}  // namespace atrium
