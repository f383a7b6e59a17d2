// Debug views (--debug-view, `g` in the window): each G-buffer target on its own,
// depth, light-volume outlines over the lit image, a heatmap of the lights
// evaluated per pixel by the current mode, the light count of each pixel's tile
// or cluster, the cluster depth slices, the fragments the mode's geometry
// passes rasterise per pixel, the diffuse and specular light sums a deferred
// mode's lighting passes wrote apart (SPLIT_LIGHTING while shown), the light
// pre-pass's light buffer, with MSAA the edge pixels the deferred modes shade
// per sample, and with shadows on the shadow atlas's depths. Views find what
// they show in the frame's graph by name (the "gbuffer.*" targets, whichever
// pass made them; "light-buffer.diffuse"; "diffuse-light"; "shadow-atlas") and
// declare reads of it, so that it lives until they have run. The G-buffer
// views show the mode's own G-buffer in its layout (the light pre-pass's thin
// one included), or in a forward mode a geometry pass of their own adds one
// (add_gbuffer_pass), so they work whatever the mode; the heatmap and the
// fragments view count what the mode's own shaders do (compiled with
// COUNT_LIGHTS or COUNT_FRAGMENTS while shown); the light-lists view draws the
// lists the tiled and clustered modes built.
// Beyond those named views, any resource a pass declares with a ViewKind
// (render/frame_graph.hpp) is a view under its own name, drawn by the
// visualiser for its kind (colour, depth, counts, light lists, shadow atlas):
// a new technique's targets are viewable with no edit here. `atrium render
// --mode M --debug-view list` prints what mode M's graph offers.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "render/gpu_assets.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/readback_ring.hpp"
#include "render/shader_globals.hpp"
#include "render/lighting/cluster_grid.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/lighting/light_index_list.hpp"
#include "render/frame/frame_context.hpp"

namespace atrium::render {

class DebugViews;

// What a shown view asks of the frame before the technique draws it.
struct DebugViewNeeds {
  bool gbuffer = false;          // a G-buffer (a forward mode's frame fills one for the view)
  bool count_lights = false;     // the technique's shaders count lights evaluated (COUNT_LIGHTS)
  bool count_fragments = false;  // the geometry passes count fragments (COUNT_FRAGMENTS)
  bool split_lighting = false;   // the diffuse and specular sums apart (SPLIT_LIGHTING)
};

// What a view draws from: the frame the technique drew and the frame's graph.
struct DebugViewFrame {
  const FrameContext& frame;
  const FrameTargets& targets;
  const FrameGraph& graph;
  glm::vec3 bounds_min, bounds_max;  // the scene's, for the position view's colours
};

// Draws a view into the bound framebuffer's viewport (origin and scale map the
// viewport to a thumbnail cell; (0, 0) and (1, 1) for the whole output).
using DrawView = void (*)(DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                          glm::vec2 scale);

// One named debug view (--debug-view, `g`, the overlay): what it shows, what
// it needs before the frame is drawn, and where its picture comes from: a
// graph resource (`resource` by name, or with `resource` empty the first one
// of `kind`) drawn by the visualiser for that resource's kind, or with `draw`
// a picture derived from the frame (the G-buffer's quantities decoded,
// outlines, depth slices). `offered`: whether a frame's graph, as its
// technique and modules built it, has what the view shows. A view whose
// frame lacks it still draws, flat grey.
struct DebugView {
  std::string_view name;
  std::string_view help;
  DebugViewNeeds needs;
  std::string_view resource;
  ViewKind kind = ViewKind::None;
  bool (*offered)(const FrameGraph& graph, const TechniqueOptions& options) = nullptr;
  DrawView draw = nullptr;
};

// Every named view, in the order `g` cycles them.
[[nodiscard]] std::span<const DebugView> debug_view_table();
// The row named `name`, or nullptr.
[[nodiscard]] const DebugView* find_debug_view(std::string_view name);
[[nodiscard]] std::string debug_view_names();

// A view a frame offers: a row of the table or a resource of the graph.
struct OfferedView {
  std::string name;
  std::string help;
};
// The named views `graph` offers, then each of its viewable resources under
// its own name (G-buffer targets are shown through the named views).
[[nodiscard]] std::vector<OfferedView> offered_views(const FrameGraph& graph, const TechniqueOptions& options);
// Their names, comma-separated: what a refused view's message lists.
[[nodiscard]] std::string view_names(const std::vector<OfferedView>& views);

// A view name that is neither a row nor a viewable resource of the frame's
// graph: bad input, which the CLI reports with exit 2.
class UnknownViewError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The view `name` selects in a frame: a table row, or else a viewable
// resource of `graph`; nullopt when it names neither.
struct SelectedView {
  const DebugView* row = nullptr;
  ResourceId resource;  // the resource it shows (a row's by name or kind); invalid: none
};
[[nodiscard]] std::optional<SelectedView> select_view(std::string_view name, const FrameGraph& graph);

class DebugViews {
 public:
  DebugViews(GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets);

  // For a view that needs a G-buffer in a frame whose technique made none:
  // the views' own geometry pass, adding "gbuffer.*" to the graph.
  void add_gbuffer_pass(FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets);
  // Heatmap and fragments views: a pass that zeroes the per-pixel counters
  // ("light-counts" or "fragment-counts", ViewKind::Counts) and binds them to
  // the image unit the technique's counting shaders write (0 for lights, 1
  // for fragments), before the technique's passes.
  void add_counting_pass(FrameGraph& graph, const DebugViewNeeds& needs);
  // The COUNT_LIGHTS and COUNT_FRAGMENTS rows of the shader globals
  // (render/shader_globals.hpp): the heatmap and fragments views' counters.
  static void counting_defines(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.count_lights) defines.push_back({"COUNT_LIGHTS"});
    if (inputs.count_fragments) defines.push_back({"COUNT_FRAGMENTS"});
  }
  // Declares the reads of what `view` shows (the G-buffer, its resource, the
  // scene depth) in the pass that draws it.
  static void declare_reads(const SelectedView& view, PassBuilder& pass, const FrameGraph& graph, const FrameContext& frame);
  // Draws `view` into `output_framebuffer` (already holding the tone-mapped
  // image) after the technique has drawn the frame.
  void draw(const SelectedView& view, const DebugViewFrame& frame, const PassResources& res, GLuint output_framebuffer);
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
  // metallic-roughness, emissive, depth) of the frame's G-buffer, decoded as
  // the debug views decode them, and the diffuse and specular light sums (grey
  // while the split is off), side by side in one texture of kThumbnailColumns
  // x 2 cells of kThumbnailWidth pixels across (rows bottom-up, as GL stores them).
  static constexpr int kThumbnailWidth = 192, kThumbnailColumns = 4, kThumbnailCount = 8;
  // The debug view each thumbnail shows, in order.
  static constexpr std::array<std::string_view, kThumbnailCount> kThumbnailViews{
      "position", "normal", "albedo", "metallic-roughness", "emissive", "depth", "diffuse-light", "specular-light"};
  void draw_thumbnails(const DebugViewFrame& frame, const PassResources& res);
  // Declares the reads of what the thumbnails show.
  static void declare_thumbnail_reads(PassBuilder& pass, const FrameGraph& graph, const FrameContext& frame);
  [[nodiscard]] GLuint thumbnails() const { return thumbnails_.id(); }
  [[nodiscard]] glm::ivec2 thumbnail_size() const { return thumbnail_size_; }

  // What the rows and visualisers draw with, each into the bound
  // framebuffer's viewport. One G-buffer quantity (`target`: the show.frag
  // define SHOW_<TARGET>), decoded in the layout of the frame's G-buffer.
  void show_gbuffer(std::string_view target, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                    glm::vec2 scale);
  // A depth resource as view depth on a log scale, near white.
  void show_depth(ResourceId depth, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                  glm::vec2 scale);
  // A counts resource as a heatmap (lights: topping out at twice the light
  // count, forward's overdraw can exceed one pass over all lights; fragments: at 64).
  void show_counts(ResourceId counts, const DebugViewFrame& frame, const PassResources& res);
  // Each pixel's tile or cluster list length, from the lists `bins` (the
  // frame's published LightBins); flat grey for lists nobody described.
  void show_light_bins(ResourceId lists, const DebugViewFrame& frame, const PassResources& res);
  // Each pixel's cluster depth slice, in any mode.
  void show_depth_slices(const DebugViewFrame& frame, const PassResources& res);
  // A colour or light resource, exposed and tone-mapped (with the thumbnail mapping).
  void show_light_sum(ResourceId sum, const PassResources& res, glm::vec2 origin, glm::vec2 scale);
  // A shadow atlas's depths.
  void show_shadow_atlas(ResourceId atlas, const PassResources& res);
  // Identifiers (R32UI) as colours: each value, or the visibility buffer's
  // draw (primitive instance) or material that a triangle identifier names;
  // or, blended over the image, the pixels whose samples show several surfaces.
  enum class Identify { Value, Draw, Material, Shared };
  void show_identifiers(ResourceId identifiers, const PassResources& res, Identify what);
  // A full-screen debug shader over the frame's G-buffer (outlines, MSAA
  // edges), blended over the image when `blend`.
  void show_over_gbuffer(const char* fragment_shader, const DebugViewFrame& frame, const PassResources& res, bool blend);
  // Flat grey in the viewport: what a view shows when its frame lacks it.
  void show_nothing();

 private:
  // Draws `view` into the bound framebuffer's viewport.
  void draw_into_viewport(const SelectedView& view, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                          glm::vec2 scale);
  // shaders/debug/show.frag with `defines`, mapped to the viewport.
  void draw_show(const std::vector<gfx::ShaderDefine>& defines, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale);

  GpuAssets& gpu_;
  lighting::GBuffer gbuffer_;
  // The slicing the clustered modes use with these options, for depth-slices
  // in any mode; made when that view is first shown.
  ClusterGridSize cluster_grid_;
  ZSlicing z_slicing_;
  int samples_ = 1;  // of the frame's targets (TechniqueOptions::msaa)
  std::unique_ptr<lighting::ClusterGrid> slicing_;
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

}  // namespace atrium::render
