// How a system that draws joins the frame: it registers a contributor here (a
// registry resource), and every frame the renderer calls it to add its passes
// to the frame graph, after the lighting technique's passes and before tone
// mapping, with the frame's context (draw list, lights, scene targets). The
// contributor declares what its passes read and write, so it needs no change
// to any renderer file.
#pragma once

#include <functional>
#include <vector>

#include "ecs/registry.hpp"
#include "render/frame_graph.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {

using RenderContributor =
    std::function<void(render::FrameGraph& graph, ecs::Registry& registry, const lighting::FrameContext& frame, const lighting::FrameTargets& targets)>;

struct RenderContributors {
  // Called in order, after the technique's passes: they draw into the lit HDR
  // image (FrameContext::scene_color) with the scene's depth.
  std::vector<RenderContributor> after_lighting;
  // Called in order after the frame is presented to the window
  // (RendererSettings::present_to_window): their passes bind the window's
  // framebuffer (0) and draw over it, such as the overlay.
  std::vector<RenderContributor> on_window;
};

}  // namespace atrium
