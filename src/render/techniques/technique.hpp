// The one interface every lighting technique implements, and the technique table
// that names them. A technique contributes the passes that draw the frame's lit,
// linear HDR image into the renderer's colour target (with depth in its
// depth-stencil target) to the frame graph; the renderer's own passes then
// tone-map it. Adding a technique is one folder beside this file (its C++;
// CMake finds it), the shaders/ folder of the same name, and one row in
// technique_table.cpp.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "render/gpu_assets.hpp"
#include "gfx/gl.hpp"
#include "render/binding_slots.hpp"
#include "render/frame_graph.hpp"
#include "components/technique_options.hpp"
#include "render/light_buffer.hpp"
#include "render/lighting/cluster_lights.hpp"
#include "render/frame/draw_list.hpp"
#include "render/frame/frame_context.hpp"

namespace atrium::techniques {

class LightingTechnique {
 public:
  virtual ~LightingTechnique() = default;
  // Called before the first frame and whenever the renderer's targets change
  // (their size), for what a technique keeps across frames (light lists sized
  // per tile); its per-frame targets are transients its passes create.
  virtual void resize(const render::FrameTargets& /*targets*/) {}
  // Adds the technique's passes (G-buffer, light assignment, lighting,
  // blended surfaces...) to the frame's graph. They run when the graph runs,
  // before render() returns, so they may keep references to frame and targets.
  virtual void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) = 0;
  // Technique-specific controls for the overlay; most techniques have none.
  virtual void draw_ui() {}
  // Techniques with light lists report their size and how many frames' lists
  // did not fit (the lights that did not fit were shaded wherever they reach;
  // the list grew), as
  // far as the GPU has reported them: asking takes in what has arrived and
  // never waits.
  struct ListStats {
    std::uint32_t entries = 0;
    std::uint32_t overflowed_frames = 0;
    LightAssignment assignment = LightAssignment::Automatic;  // the latest frame's (Automatic: built on the CPU)
    double density = 0.0;  // LightIndexList::last_density()
  };
  [[nodiscard]] virtual ListStats light_lists() { return {}; }
  // What the technique chose where the options left it a choice, for the
  // stats lines ("material binding bindless"); empty for most.
  [[nodiscard]] virtual std::string variant() const { return {}; }

 protected:
  // The stats of clustered lists (clustered modes, the visibility buffer).
  [[nodiscard]] static ListStats cluster_list_stats(lighting::ClusterLights& clusters) {
    if (clusters.compute_free()) return {clusters.cpu_entries(), 0};
    lighting::LightIndexList& list = clusters.list();
    list.poll();
    return {list.last_total(), list.overflow_frames(), list.last_assignment(), list.last_density()};
  }
};

// Which of a technique's shaders loop over every light, so that a driver's loop
// limit (gfx::shader_loop_limit) caps the light count it can draw.
struct LightLoops {
  bool opaque = false;   // each pixel's shading
  bool blended = false;  // the shading of blended surfaces
};

// Which G-buffer a technique keeps: none (forward modes), one in the layout
// users choose (--gbuffer), or one in a layout of its own (the light pre-pass's
// thin one). Tests run the --gbuffer layouts only where they change something.
enum class GBufferUse : std::uint8_t { None, Chosen, Own };

// What a technique needs of the context and the options; a combination it
// lacks is refused in one line (refusal()), and a tier that lacks what it
// needs leaves it out of `t`, the overlay's and the page's mode lists.
struct ModeNeeds {
  // Compute shaders and storage buffers, which the compute-free tier (OpenGL
  // 4.1, ES 3.0, WebGL2) lacks.
  bool compute = false;
};

struct TechniqueInfo {
  std::string_view name;         // the mode name users type (--mode, `t`)
  std::string_view description;  // one line for --help and the overlay
  LightLoops loops_over_every_light;
  GBufferUse gbuffer;
  ModeNeeds needs;
  // Makes the technique; it takes its shader programs from gpu.shaders().
  std::unique_ptr<LightingTechnique> (*create)(render::GpuAssets& gpu, const TechniqueOptions& options);
};

[[nodiscard]] std::span<const TechniqueInfo> technique_table();
// nullptr when no technique has that name.
[[nodiscard]] const TechniqueInfo* find_technique(std::string_view name);
// The mode names in table order.
[[nodiscard]] std::vector<std::string> mode_names();
// Those that run with `options` (refusal() is empty: their tier, MSAA), in
// table order: what `t`, menus and sweeps offer.
[[nodiscard]] std::vector<std::string> mode_names(const TechniqueOptions& options);
// Why `info` cannot run with `options` (their tier and MSAA), in one line;
// empty when it can.
[[nodiscard]] std::string refusal(const TechniqueInfo& info, const TechniqueOptions& options);
// "forward, deferred, ..." for messages.
[[nodiscard]] std::string technique_names();

}  // namespace atrium::techniques
