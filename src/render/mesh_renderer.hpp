// The MeshRenderer system (Render phase): owns the frame's long-lived render
// targets, the G-buffer choice, the lighting technique selected by
// RendererSettings::mode and the frame graph. Each frame it gathers the draw
// list and fills the frame uniforms, imports its targets into the graph, then
// lets every module add its passes stage by stage (render/frame/frame_modules.hpp:
// its own, such as shadows, the technique, tone map, debug views and present,
// and the systems' render::FrameModules), compiles the graph and runs it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "ecs/scheduler.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/pass_timer.hpp"
#include "render/debug/debug_view_module.hpp"
#include "render/frame/frame_draws.hpp"
#include "render/frame/frame_modules.hpp"
#include "render/frame_graph.hpp"
#include "render/gpu_assets.hpp"
#include "render/post/tonemap/tonemap_pass.hpp"
#include "render/shadows/shadow_atlas.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::render {

struct FrameStats {
  std::size_t draw_calls = 0;       // multi-draws one geometry pass issues (opaque and blended)
  std::size_t triangles = 0;        // in the scene
  std::size_t triangles_drawn = 0;  // one geometry pass submits, after frustum and occlusion culling
  std::size_t triangles_occluded = 0;  // in view, but hidden behind what the first pass drew
  bool culled_on_gpu = false;       // occlusion culling ran on the GPU: the two counts above arrive a frame or more late
  // Where the full-screen passes ran (--lighting-stage resolved): Fragment or Compute.
  LightingStage lighting_stage = LightingStage::Fragment;
  std::size_t objects = 0;          // entities with a mesh
  std::size_t objects_drawn = 0;    // of which the camera sees some primitive
  std::uint32_t lights = 0;
  // Measured while the heatmap (fragments view) is shown; the newest average
  // that has come back, a frame or more late (settle() waits for the last).
  double light_evaluations_per_pixel = 0.0;  // lights evaluated per pixel
  double fragments_per_pixel = 0.0;          // rasterised by geometry passes
  std::uint32_t light_list_entries = 0;      // tiled and clustered modes
  std::uint32_t light_list_overflows = 0;    // frames whose lists did not fit (counted as their totals arrive)
  LightAssignment light_assignment = LightAssignment::Automatic;  // the latest frame's (light_assignment_label)
  double light_list_density = 0.0;  // what the choice of assignment went by (LightIndexList::last_density)
  shadows::ShadowStats shadows;              // maps drawn and reused (--shadows)
  std::uint32_t gpu_waits = 0;               // calls in the frame that could wait for the GPU (gfx/gpu_waits.hpp)
  // How long the frame waited before it began for the GPU to finish the frame
  // kFramesInFlight before it (gfx/frame_pacer.hpp): above 0, the GPU sets the pace.
  double paced_ms = 0.0;
  std::string technique_variant;             // LightingTechnique::variant(): "material binding bindless"
};

class MeshRenderer {
 public:
  explicit MeshRenderer(GpuAssets& gpu);
  ~MeshRenderer();

  // Renders one frame of the registry's world. Throws std::invalid_argument for
  // a mode that is not in the technique table.
  void render(ecs::Registry& registry);

  // Waits for the GPU and takes in what it reports a frame or more late
  // (light-list totals, pass timings) into stats() and timer(): for one-shot
  // commands after a frame, never inside one (a counted GPU wait).
  void settle();

  // The last frame's display image (sRGB, top row first).
  [[nodiscard]] assets::Image read_output() const;
  // The last frame's view depth (metres along the view axis) per pixel, top
  // row first; infinity where no geometry was drawn. With MSAA the targets
  // below are read resolved (colour: samples averaged; depth: one sample).
  [[nodiscard]] std::vector<float> read_view_depth() const;
  // The last frame's linear HDR colour as lit (before post-processing), or
  // with the split on its diffuse or specular light sum, as RGBA floats in
  // GL's row order (bottom row first); empty for a sum while the split is off.
  enum class HdrTarget { Color, DiffuseLight, SpecularLight };
  [[nodiscard]] std::vector<glm::vec4> read_hdr(HdrTarget target) const;

  [[nodiscard]] const std::string& mode() const { return mode_; }
  // The technique that drew the last frame (tests and tools inspect it).
  [[nodiscard]] const techniques::LightingTechnique* technique() const { return technique_.get(); }
  // The G-buffer thumbnails of the last frame (see DebugViews::draw_thumbnails),
  // 0 when the frame drew none (setting off, or a forward mode).
  [[nodiscard]] GLuint gbuffer_thumbnails() const { return debug_.thumbnails(); }
  [[nodiscard]] glm::ivec2 thumbnail_size() const { return debug_.thumbnail_size(); }
  [[nodiscard]] const FrameStats& stats() const { return stats_; }
  [[nodiscard]] glm::ivec2 size() const { return size_; }
  // Per-pass times of the latest frame whose timings are complete (each pass
  // of the frame graph is timed by it).
  [[nodiscard]] const gfx::PassTimer& timer() const { return timer_; }
  [[nodiscard]] gfx::PassTimer& timer() { return timer_; }
  // The debug views the last frame's graph offered (its technique's and
  // modules' passes made what they show), and whether it offered `view`.
  [[nodiscard]] const std::vector<OfferedView>& offered_views() const { return debug_.offered_views(); }
  [[nodiscard]] bool offers(std::string_view view) const;
  // The last frame's graph: its passes, resources and render-target memory.
  [[nodiscard]] const FrameGraph& graph() const { return graph_; }
  // The shadow maps of the last frame (RendererSettings::shadows).
  [[nodiscard]] const shadows::ShadowAtlas& shadow_atlas() const { return shadows_; }
  // The renderer's own modules, stage by stage (the frame runs each stage's
  // own modules, then the systems' of that stage: render/frame/frame_modules.hpp).
  [[nodiscard]] const std::vector<FrameModule>& own_modules() const { return modules_; }

  // Drops the technique and every module's programs; the next frame makes
  // them again from the shader library (after a shader reload).
  void recreate_technique();

 private:
  // A single-sample copy of a multisampled target, for reading back.
  [[nodiscard]] gfx::Texture resolve(GLuint texture, GLenum format, bool depth) const;
  void make_shader_writes_readable() const;
  // Compiles programs with the settings' global defines; on a change drops
  // the technique and calls every module's invalidate hook. Returns what the
  // shown debug view asks of the frame.
  DebugViewNeeds apply_settings(ecs::Registry& registry, const RendererSettings& settings);
  void resize(ecs::Registry& registry, glm::ivec2 size);
  // Makes the diffuse and specular light targets while split_lighting_ is
  // on, drops them while it is off.
  void update_split_targets();
  void invalidate_modules(ecs::Registry& registry);
  // The frame's draws, uniforms and shadow choice, before the graph is built.
  void begin_frame(ecs::Registry& registry, const RendererSettings& settings, LightBuffer& lights);
  // The renderer's long-lived targets in the graph, as the frame's context.
  [[nodiscard]] FrameContext import_targets(ecs::Registry& registry, const LightBuffer& lights);
  // Every module's passes, stage by stage.
  void add_modules(FrameBuild& build);
  // Takes what the GPU reported a frame or more late and has arrived into
  // `stats`: the counters' averages (DebugViews::take_averages) for the views
  // the last frame counted, and the light lists' totals. Never waits.
  void take_reports(FrameStats& stats);
  void select_technique(const std::string& mode);
  [[nodiscard]] FrameTargets targets() const;
  // Throws gfx::ResourceLimitError when the driver limits shader loops and a
  // pixel of this frame would loop over more lights than that limit.
  void refuse_unbounded_loops(const DrawList& draws, std::uint32_t light_count) const;

  glm::ivec2 size_{0};
  std::string mode_;
  TechniqueOptions technique_options_;
  std::vector<gfx::ShaderDefine> globals_;  // what every program is compiled with (render/shader_globals.hpp)
  bool split_lighting_ = false;  // the light-sum targets exist (shaders compiled with SPLIT_LIGHTING)
  bool reload_pending_ = false;  // recreate_technique(): the next frame calls every module's invalidate hook
  std::unique_ptr<techniques::LightingTechnique> technique_;
  gfx::Texture hdr_color_;
  gfx::Texture depth_stencil_;
  gfx::Texture diffuse_light_, specular_light_;  // with the split on (split_lighting_)
  gfx::Texture output_color_;
  gfx::Buffer frame_uniforms_;
  GpuAssets& gpu_;
  FrameDraws draws_;
  shadows::ShadowAtlas shadows_;
  DebugViewModule debug_;
  TonemapPass tonemap_;
  std::vector<FrameModule> modules_;  // the renderer's own, in stage order
  FrameStats stats_;        // the last complete frame's (what passes of this frame, like the overlay, show)
  FrameStats frame_stats_;  // the frame being drawn
  // The heatmap's and the fragments view's newest averages (they arrive a
  // frame or more late) and whether the last frame counted each.
  double light_average_ = 0.0, fragment_average_ = 0.0;
  bool counted_lights_ = false, counted_fragments_ = false;
  gfx::PassTimer timer_;
  gfx::FramePacer pacer_;
  FrameGraph graph_;  // the frame's passes; its pool keeps transient targets between frames
  std::uint32_t loop_limit_;  // gfx::shader_loop_limit(), asked once
  glm::vec2 planes_{0.05f, 200.0f};  // the last frame's near and far planes
};

// Adds the MeshRenderer to the Render phase. The world must hold the resources
// AssetManager, GpuAssets, Viewport, ViewState, SceneSettings, RendererSettings
// and a MeshRenderer (constructed with a current GL context).
void register_mesh_renderer(ecs::Scheduler& scheduler);

}  // namespace atrium::render
