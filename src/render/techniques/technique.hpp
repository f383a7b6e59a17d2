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
#include "render/frame/draw_list.hpp"

namespace atrium::lighting {

// A function that draws batches of the frame's draw list from `source` with
// the caller's program and state (what the first pass over opaque geometry is
// given; draw_items is one).
using BatchDrawer = std::function<void(std::span<const DrawBatch>, const CommandSource& source)>;

// What a technique reads each frame. The frame uniform block and the light
// storage buffer are already bound at kFrameUniformBinding / kLightStorageBinding.
struct FrameContext {
  // The frame's visible geometry. Until the first pass over opaque geometry
  // has run, `opaque` holds only what the last frame showed; after it, all
  // that pass drew (occlusion culling, render/culling/occlusion_culling.hpp).
  const DrawList& draws;
  // Where the passes after the first draw the list's commands from
  // (draw_items); FrameDraws sets it as occlusion culling's phases go.
  const CommandSource& commands;
  // The first pass over opaque geometry (the one that fills the depth buffer)
  // draws through this, never over draws.opaque itself: it calls `draw` with
  // what the last frame showed, tests the rest against the depth just written,
  // and calls `draw` again with what that depth does not hide. `draw` may rely
  // on the program in use and the pass's GL state surviving between the calls.
  std::function<void(const BatchDrawer& draw)> draw_first_pass;
  const assets::GpuAssets& gpu;
  std::span<const GpuLight> lights;  // CPU copy of the light buffer's contents
  glm::vec3 background{0.0f};
  // The renderer's long-lived resources in the frame graph: the scene's
  // depth-stencil and HDR colour (FrameTargets), and the light buffer.
  render::ResourceId scene_depth, scene_color, light_buffer;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  float near_plane = 0.05f;
  float far_plane = 200.0f;
  // With the split on (TechniqueOptions::split_lighting), the diffuse and
  // specular light sums a deferred lighting pass writes; invalid otherwise.
  render::ResourceId diffuse_light{}, specular_light{};
  // The shadow maps (RendererSettings::shadows); invalid while shadows are off.
  render::ResourceId shadow_atlas{};
};

// The framebuffer of the lit image and the scene's depth-stencil, from the
// graph (a pass that draws into them declares it writes scene_color).
inline GLuint scene_framebuffer(const render::PassResources& res, const FrameContext& frame) {
  return res.framebuffer({frame.scene_color}, frame.scene_depth);
}
// Where deferred lighting passes draw (shaders/common/lighting_targets.glsl):
// the lit image, and with the split on the diffuse and specular light sums
// as colour attachments 1 and 2; the scene's depth-stencil.
inline GLuint lighting_framebuffer(const render::PassResources& res, const FrameContext& frame) {
  if (!frame.diffuse_light.valid()) return scene_framebuffer(res, frame);
  return res.framebuffer({frame.scene_color, frame.diffuse_light, frame.specular_light}, frame.scene_depth);
}

// What every pass that shades reads besides its own inputs: the lights and,
// with shadows on, the shadow atlas, which the graph binds at its unit (and
// orders the pass after the shadow maps are drawn, keeping the maps' pass).
inline void read_shading_inputs(render::PassBuilder& pass, const FrameContext& frame) {
  pass.read(frame.light_buffer, render::Access::Storage);
  if (frame.shadow_atlas.valid()) pass.sample_at(frame.shadow_atlas, render::kShadowAtlasUnit);
}

// The shape of the frame's targets (owned by the MeshRenderer). Their GL
// objects are the graph's: a pass reaches them through PassResources and the
// FrameContext's resource handles (scene_framebuffer, lighting_framebuffer).
struct FrameTargets {
  glm::ivec2 size{0};
  int samples = 1;  // MSAA samples of the scene's targets (TechniqueOptions::msaa)
};

class LightingTechnique {
 public:
  virtual ~LightingTechnique() = default;
  // Called before the first frame and whenever the renderer's targets change
  // (their size), for what a technique keeps across frames (light lists sized
  // per tile); its per-frame targets are transients its passes create.
  virtual void resize(const FrameTargets& /*targets*/) {}
  // Adds the technique's passes (G-buffer, light assignment, lighting,
  // blended surfaces...) to the frame's graph. They run when the graph runs,
  // before render() returns, so they may keep references to frame and targets.
  virtual void add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) = 0;
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

struct TechniqueInfo {
  std::string_view name;         // the mode name users type (--mode, `t`)
  std::string_view description;  // one line for --help and the overlay
  LightLoops loops_over_every_light;
  GBufferUse gbuffer;
  // Makes the technique; it takes its shader programs from gpu.shaders().
  std::unique_ptr<LightingTechnique> (*create)(assets::GpuAssets& gpu, const TechniqueOptions& options);
};

[[nodiscard]] std::span<const TechniqueInfo> technique_table();
// nullptr when no technique has that name.
[[nodiscard]] const TechniqueInfo* find_technique(std::string_view name);
// The mode names in table order (for `t`, menus and sweeps).
[[nodiscard]] std::vector<std::string> mode_names();
// "forward, deferred, ..." for messages.
[[nodiscard]] std::string technique_names();

}  // namespace atrium::lighting
