// The debug views as frame modules. "counters" (before lighting): with the
// heatmap or fragments view shown, zeroes the per-pixel counters the frame's
// shaders add to. "debug view" (output): the overlay's G-buffer thumbnails
// and the selected --debug-view, drawn over the output from any resource the
// frame's graph holds (render/debug/debug_views.hpp). Reads
// RendererSettings::debug_view and gbuffer_thumbnails; writes the output.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "render/debug/debug_views.hpp"
#include "render/frame/frame_modules.hpp"

namespace atrium::render {

class DebugViewModule {
 public:
  explicit DebugViewModule(GpuAssets& gpu) : gpu_(gpu) {}

  [[nodiscard]] FrameModule counters_module();
  [[nodiscard]] FrameModule view_module();

  // What the shown view (RendererSettings::debug_view) asks of the frame
  // before its programs are compiled; nothing for a view of a resource by name.
  [[nodiscard]] static DebugViewNeeds needs(std::string_view view);

  // The views the last frame's graph offered, before the views' own passes.
  [[nodiscard]] const std::vector<OfferedView>& offered_views() const { return offered_; }
  // The G-buffer thumbnails of the last frame; 0 when it drew none.
  [[nodiscard]] GLuint thumbnails() const { return thumbnails_drawn_ && views_ ? views_->thumbnails() : 0; }
  [[nodiscard]] glm::ivec2 thumbnail_size() const { return views_ ? views_->thumbnail_size() : glm::ivec2(0); }
  // The counters' averages that have come back (DebugViews::take_averages).
  [[nodiscard]] std::vector<DebugViews::CountAverage> take_averages();
  // The module's one hook: programs and targets are remade on next use.
  void invalidate() { views_.reset(); }

 private:
  DebugViews& views(const FrameBuild& build);

  GpuAssets& gpu_;
  std::unique_ptr<DebugViews> views_;  // made on first use, with the frame's options and targets
  std::vector<OfferedView> offered_;
  bool thumbnails_drawn_ = false;
  std::optional<DebugViewFrame> view_frame_;  // this frame's, for the passes' execution
  std::optional<SelectedView> selected_;
};

}  // namespace atrium::render
