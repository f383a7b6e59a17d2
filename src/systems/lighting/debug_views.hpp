// Debug views (--debug-view, `g` in the window): each G-buffer target on its own,
// depth, light-volume outlines over the lit image, and a heatmap of the lights
// evaluated per pixel by the current mode. The G-buffer views run their own
// geometry pass, so they work whatever the mode; the heatmap counts what the
// mode's own shaders do (they are compiled with COUNT_LIGHTS while it is shown).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "assets/gpu_assets.hpp"
#include "gfx/gl_object.hpp"
#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

inline constexpr std::array<std::string_view, 8> kDebugViews{
    "position", "normal", "albedo", "metallic-roughness", "emissive", "depth", "light-volumes", "heatmap"};
inline constexpr int kDepthView = 5, kOutlineView = 6, kHeatmapView = 7;

// The index of a debug view name in kDebugViews, or -1.
[[nodiscard]] int debug_view_index(std::string_view name);
[[nodiscard]] std::string debug_view_names();

class DebugViews {
 public:
  explicit DebugViews(assets::GpuAssets& gpu);
  void resize(const FrameTargets& targets);

  // Heatmap: zeroes the per-pixel counters and binds them to image unit 0 for
  // the technique's shaders.
  void begin_counting();
  // Draws `view` into `output_framebuffer` (already holding the tone-mapped image).
  void draw(int view, const FrameContext& frame, const FrameTargets& targets, GLuint output_framebuffer,
            glm::vec3 bounds_min, glm::vec3 bounds_max);
  // Heatmap: light evaluations per pixel, averaged over the image.
  [[nodiscard]] double average_light_evaluations() const;

 private:
  assets::GpuAssets& gpu_;
  GBuffer gbuffer_;
  FullscreenTriangle fullscreen_;
  gfx::Texture counts_;
  glm::ivec2 size_{0};
};

}  // namespace atrium::lighting
