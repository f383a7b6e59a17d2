// Debug views (--debug-view, `g` in the window): each G-buffer target on its own,
// depth, light-volume outlines over the lit image, a heatmap of the lights
// evaluated per pixel by the current mode, the light count of each pixel's tile
// or cluster, the cluster depth slices, the fragments the mode's geometry
// passes rasterise per pixel, the diffuse and specular light sums a deferred
// mode's lighting passes wrote apart (SPLIT_LIGHTING while shown), and the light
// pre-pass's light buffer (LightingTechnique::light_buffer), and with MSAA the
// edge pixels the deferred modes shade per sample, and with shadows on the
// shadow atlas's depths. The G-buffer views
// show the mode's own G-buffer in its layout (the light pre-pass's thin one
// included), or in a forward mode run a geometry pass of their own, so they work
// whatever the mode; the heatmap and the fragments view count what the mode's
// own shaders do (compiled with COUNT_LIGHTS or COUNT_FRAGMENTS while shown);
// the light-lists view draws the lists the tiled and clustered modes built.
// Every view is one row of debug_view_table() carrying its own code; `atrium
// render --mode M --debug-view list` prints the rows mode M offers.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "assets/gpu_assets.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/readback_ring.hpp"
#include "render/shader_globals.hpp"
#include "systems/lighting/cluster_grid.hpp"
#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

class DebugViews;

// What a shown view asks of the frame before the technique draws it.
struct DebugViewNeeds {
  bool gbuffer = false;          // a G-buffer (a forward mode's frame fills one for the view)
  bool count_lights = false;     // the technique's shaders count lights evaluated (COUNT_LIGHTS)
  bool count_fragments = false;  // the geometry passes count fragments (COUNT_FRAGMENTS)
  bool split_lighting = false;   // the diffuse and specular sums apart (SPLIT_LIGHTING)
};

// What a view draws from: the frame the technique drew.
struct DebugViewFrame {
  const LightingTechnique& technique;
  const FrameContext& frame;
  const FrameTargets& targets;
  glm::vec3 bounds_min, bounds_max;  // the scene's, for the position view's colours
  GLuint shadow_atlas;               // 0 while shadows are off
};

// One debug view: its name (--debug-view, `g`, the overlay), what it shows,
// what it needs, whether a mode offers it, and the code that draws it into
// the bound framebuffer's viewport (origin and scale map the viewport to a
// thumbnail cell; (0, 0) and (1, 1) for the whole output). A view that a mode
// does not offer still draws, flat grey where it has nothing to show.
struct DebugView {
  std::string_view name;
  std::string_view help;
  DebugViewNeeds needs;
  bool (*offered)(const LightingTechnique& technique, const TechniqueOptions& options, int shadows);
  void (*draw)(DebugViews& views, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale);
};

// Every debug view, in the order `g` cycles them.
[[nodiscard]] std::span<const DebugView> debug_view_table();
// The row named `name`, or nullptr.
[[nodiscard]] const DebugView* find_debug_view(std::string_view name);
[[nodiscard]] std::string debug_view_names();

class DebugViews {
 public:
  DebugViews(assets::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets);

  // Heatmap and fragments views: zeroes the per-pixel counters and binds them
  // to the image unit the technique's counting shaders write (0 for lights, 1
  // for fragments).
  void begin_counting(const DebugViewNeeds& needs);
  // The COUNT_LIGHTS and COUNT_FRAGMENTS rows of the shader globals
  // (render/shader_globals.hpp): the heatmap and fragments views' counters.
  static void counting_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.count_lights) defines.push_back({"COUNT_LIGHTS"});
    if (inputs.count_fragments) defines.push_back({"COUNT_FRAGMENTS"});
  }
  // Draws `view` into `output_framebuffer` (already holding the tone-mapped
  // image) after the technique has drawn the frame.
  void draw(const DebugView& view, const DebugViewFrame& frame, GLuint output_framebuffer);
  // Heatmap and fragments views: sums this frame's counters per block and
  // sends the sums back (gfx::ReadbackRing) to be averaged a frame or more
  // later; nothing waits.
  void send_counts(const DebugViewNeeds& needs);
  // The averages whose sums have arrived since the last call, newest last:
  // counts per pixel, and whether they counted fragments (else lights).
  struct CountAverage {
    double per_pixel = 0.0;
    bool fragments = false;
  };
  [[nodiscard]] std::vector<CountAverage> take_averages();

  // The overlay's thumbnails: the G-buffer views (position, normal, albedo,
  // metallic-roughness, emissive, depth) of `gbuffer`, decoded as the debug
  // views decode them, and the diffuse and specular light sums (grey while the
  // split is off), side by side in one texture of kThumbnailColumns x 2 cells
  // of kThumbnailWidth pixels across (rows bottom-up, as GL stores them).
  static constexpr int kThumbnailWidth = 192, kThumbnailColumns = 4, kThumbnailCount = 8;
  // The debug view each thumbnail shows, in order.
  static constexpr std::array<std::string_view, kThumbnailCount> kThumbnailViews{
      "position", "normal", "albedo", "metallic-roughness", "emissive", "depth", "diffuse-light", "specular-light"};
  void draw_thumbnails(const DebugViewFrame& frame);
  [[nodiscard]] GLuint thumbnails() const { return thumbnails_.id(); }
  [[nodiscard]] glm::ivec2 thumbnail_size() const { return thumbnail_size_; }

  // What the table's rows draw with, each into the bound framebuffer's viewport.
  // One G-buffer target (`target`: the show.frag define SHOW_<TARGET>), decoded
  // in the layout of the frame's G-buffer (the technique's, else the views' own).
  void show_gbuffer(std::string_view target, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale);
  // The per-pixel counters as a heatmap topping out at `scale_max`.
  void show_counts(float scale_max);
  // Each pixel's tile or cluster list length (or, with `depth_slices`, its
  // cluster depth slice in any mode); flat grey in a mode without lists.
  void show_light_bins(bool depth_slices, const DebugViewFrame& frame);
  // A light sum (the diffuse or specular light target, the light buffer),
  // tone-mapped (with the thumbnail mapping); flat grey for 0, a sum this
  // frame did not make.
  void show_light_sum(GLuint sum, glm::vec2 origin, glm::vec2 scale);
  // The shadow atlas's depths; flat grey without one.
  void show_shadow_atlas(GLuint atlas);
  // A full-screen debug shader over the frame's G-buffer (outlines, MSAA
  // edges), blended over the image when `blend`.
  void show_over_gbuffer(const char* fragment_shader, const DebugViewFrame& frame, bool blend);

 private:
  [[nodiscard]] const GBuffer& gbuffer_of(const DebugViewFrame& frame) const { return frame.technique.gbuffer() ? *frame.technique.gbuffer() : gbuffer_; }

  assets::GpuAssets& gpu_;
  GBuffer gbuffer_;
  // The slicing the clustered modes use with these options, for depth-slices
  // in any mode; made when that view is first shown.
  glm::uvec3 cluster_dims_;
  ZSlicing z_slicing_;
  std::unique_ptr<ClusterGrid> slicing_;
  FullscreenTriangle fullscreen_;
  gfx::Sampler depth_sampler_;  // the shadow atlas read as depth values, comparison off
  gfx::Texture counts_;
  gfx::Buffer block_sums_;                   // one uint per 16x16 block of counts_
  std::unique_ptr<gfx::ReadbackRing> sums_;  // block_sums_ on their way back, tagged with what they counted
  gfx::Texture thumbnails_;
  gfx::Framebuffer thumbnail_framebuffer_;
  glm::ivec2 thumbnail_size_{0};
  glm::ivec2 size_{0};
};

}  // namespace atrium::lighting
