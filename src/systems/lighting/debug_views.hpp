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
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>

#include "assets/gpu_assets.hpp"
#include "gfx/gl_object.hpp"
#include "render/shader_globals.hpp"
#include "systems/lighting/cluster_grid.hpp"
#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

inline constexpr std::array<std::string_view, 16> kDebugViews{
    "position",     "normal",      "albedo",       "metallic-roughness", "emissive",      "depth",
    "light-volumes", "heatmap",    "light-lists",  "depth-slices",       "fragments",     "diffuse-light",
    "specular-light", "light-buffer", "msaa-edges", "shadow-atlas"};
inline constexpr int kDepthView = 5, kOutlineView = 6, kHeatmapView = 7, kLightListView = 8, kDepthSliceView = 9,
                     kFragmentView = 10, kDiffuseLightView = 11, kSpecularLightView = 12, kLightBufferView = 13,
                     kMsaaEdgeView = 14, kShadowAtlasView = 15;

// The index of a debug view name in kDebugViews, or -1.
[[nodiscard]] int debug_view_index(std::string_view name);
[[nodiscard]] std::string debug_view_names();

class DebugViews {
 public:
  DebugViews(assets::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets);

  // Heatmap and fragments views: zeroes the per-pixel counters and binds them
  // to the image unit the technique's counting shaders write (0 for lights, 1
  // for fragments).
  void begin_counting(int view);
  // The COUNT_LIGHTS and COUNT_FRAGMENTS rows of the shader globals
  // (render/shader_globals.hpp): the heatmap and fragments views' counters.
  static void counting_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.debug_view == kHeatmapView) defines.push_back({"COUNT_LIGHTS"});
    if (inputs.debug_view == kFragmentView) defines.push_back({"COUNT_FRAGMENTS"});
  }
  // Draws `view` into `output_framebuffer` (already holding the tone-mapped
  // image) after `technique` has drawn the frame; `shadow_atlas` is the
  // frame's shadow atlas texture (0 while shadows are off).
  void draw(int view, const LightingTechnique& technique, const FrameContext& frame, const FrameTargets& targets,
            GLuint output_framebuffer, glm::vec3 bounds_min, glm::vec3 bounds_max, GLuint shadow_atlas);
  // Heatmap and fragments views: the count per pixel, averaged over the image.
  [[nodiscard]] double average_count() const;

  // The overlay's thumbnails: the G-buffer views (position, normal, albedo,
  // metallic-roughness, emissive, depth) of `gbuffer`, decoded as the debug
  // views decode them, and the diffuse and specular light sums (grey while the
  // split is off), side by side in one texture of kThumbnailColumns x 2 cells
  // of kThumbnailWidth pixels across (rows bottom-up, as GL stores them).
  static constexpr int kThumbnailWidth = 192, kThumbnailColumns = 4, kThumbnailCount = 8;
  // The debug view each thumbnail shows, in order.
  static constexpr std::array<int, kThumbnailCount> kThumbnailViews{0, 1, 2, 3, 4, kDepthView, kDiffuseLightView, kSpecularLightView};
  void draw_thumbnails(const GBuffer& gbuffer, const FrameTargets& targets, glm::vec3 bounds_min, glm::vec3 bounds_max);
  [[nodiscard]] GLuint thumbnails() const { return thumbnails_.id(); }
  [[nodiscard]] glm::ivec2 thumbnail_size() const { return thumbnail_size_; }

 private:
  void draw_light_bins(int view, const LightingTechnique& technique, const FrameContext& frame, const FrameTargets& targets);
  // A G-buffer view (position .. depth) of `gbuffer`, decoded in its layout,
  // into the bound framebuffer's viewport (with the thumbnail mapping).
  void show_gbuffer(int view, const GBuffer& gbuffer, const FrameTargets& targets, glm::vec3 bounds_min, glm::vec3 bounds_max,
                    glm::vec2 origin, glm::vec2 scale);
  // A light sum (the diffuse or specular light target, the light buffer),
  // tone-mapped, into the bound framebuffer's viewport (with the thumbnail
  // mapping); flat grey for 0, a sum this frame did not make.
  void draw_light_sum(GLuint sum, glm::vec2 origin, glm::vec2 scale);

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
  gfx::Texture thumbnails_;
  gfx::Framebuffer thumbnail_framebuffer_;
  glm::ivec2 thumbnail_size_{0};
  glm::ivec2 size_{0};
};

}  // namespace atrium::lighting
