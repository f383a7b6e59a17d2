// The frame as modules of passes in named stages. Every part of the engine that
// draws (the renderer's own passes, the lighting technique, post-processing,
// the systems that draw, the overlay) is a module: a function that adds
// passes to the frame graph, registered into one stage. The frame runs the
// stages in the order of FrameStage and, within a stage, the modules in the
// order they were registered, so order is declared by the stage a module names.
// A module reaches the frame's targets only through the graph (FrameBuild's
// resource handles and PassResources); the colour image is a handle that each
// post-process pass takes and replaces with the one it writes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/registry.hpp"
#include "render/frame_graph.hpp"
#include "render/frame/frame_context.hpp"

namespace atrium::render {

enum class FrameStage : std::uint8_t {
  BeforeLighting,  // what lighting reads and no technique makes: occlusion culling, shadow maps, cleared light sums, counters
  Lighting,        // the technique: the lit, linear HDR image with the scene's depth
  AfterLighting,   // drawn into the lit image with its depth (a system's sprites, blended effects)
  PostProcess,     // HDR to HDR, each pass taking FrameBuild::color and leaving the image it wrote (a glow, a blur)
  Output,          // HDR to the 8-bit output: tone map, debug views, thumbnails
  Window,          // after the output is presented, over the window (the overlay)
};
inline constexpr std::array<std::string_view, 6> kFrameStageNames{"before lighting", "lighting", "after lighting",
                                                                  "post-process",    "output",   "window"};

// What a module is given while the frame's graph is built.
struct FrameBuild {
  FrameGraph& graph;
  ecs::Registry& registry;
  const FrameContext& frame;
  const FrameTargets& targets;
  // The frame's colour image: the lit HDR image (frame.scene_color) until a
  // post-process pass sets the image it wrote in its place; the output stage
  // tone-maps what is here at its start.
  ResourceId color;
  ResourceId output;  // the 8-bit display image (RGBA8, single sample)
};

struct FrameModule {
  FrameStage stage;
  std::string name;
  // Adds the module's passes; they run when the graph executes, before the
  // frame's render() returns, so they may keep references to `build`'s parts.
  std::function<void(FrameBuild&)> add_passes;
  // The one hook for the frame's settings: called when the programs or
  // targets made before are stale (shader globals, technique options, size),
  // so the module drops the programs and targets it made from them. May be empty.
  std::function<void()> invalidate;
};

// The modules of systems (a registry resource): a system that draws adds its
// module here when it registers, and touches no renderer file.
class FrameModules {
 public:
  void add(FrameModule module) { modules_.push_back(std::move(module)); }
  [[nodiscard]] const std::vector<FrameModule>& modules() const { return modules_; }

 private:
  std::vector<FrameModule> modules_;
};

}  // namespace atrium::render
