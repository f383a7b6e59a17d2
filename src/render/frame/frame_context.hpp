// What every pass of the frame is given: the frame's draws, its lights, its
// camera and the graph handles of the renderer's long-lived targets
// (FrameContext), and the targets' shape (FrameTargets). Techniques, the
// renderer's own modules and systems' modules all read the frame through these.
#pragma once

#include <functional>
#include <span>

#include <glm/glm.hpp>

#include "render/binding_slots.hpp"
#include "render/frame/draw_list.hpp"
#include "render/frame_graph.hpp"
#include "render/gpu_assets.hpp"
#include "render/light_buffer.hpp"

namespace atrium::render {

// A function that draws batches of the frame's draw list from `source` with
// the caller's program and state (what the first pass over opaque geometry is
// given; draw_items is one).
using BatchDrawer = std::function<void(std::span<const DrawBatch>, const CommandSource& source)>;

class FrameDraws;

// The frame's draw buffers in the graph: the instance records, the materials
// and the indirect commands (with occlusion culling on the GPU, the commands
// its pass writes for the passes after it). Invalid on the compute-free tier,
// whose records are textures and whose commands stay on the CPU.
struct DrawResources {
  ResourceId instances, slots, materials, commands;
};

// What a technique reads each frame. The frame uniform block and the light
// storage buffer are already bound at kFrameUniformBinding / kLightStorageBinding.
struct FrameContext {
  // The frame's visible geometry and where its commands are drawn from, with
  // one owner (render/frame/frame_draws.hpp): draws.list() and
  // draws.commands(), read when a pass runs. Both advance with occlusion
  // culling's phases: until the first pass over opaque geometry has run,
  // list().opaque holds only what the last frame showed; after it, all that
  // pass drew (render/culling/occlusion_culling.hpp).
  const FrameDraws& draws;
  // The first pass over opaque geometry (the one that fills the depth buffer)
  // draws through this, never over the list itself: it calls `draw` with
  // what the last frame showed, tests the rest against the depth just written
  // (scene_depth, through `res`), and calls `draw` again with what that depth
  // does not hide. `draw` may rely on the program in use and the pass's GL
  // state surviving between the calls.
  std::function<void(const PassResources& res, const BatchDrawer& draw)> draw_first_pass;
  const GpuAssets& gpu;
  std::span<const GpuLight> lights;  // CPU copy of the light buffer's contents
  glm::vec3 background{0.0f};
  // The renderer's long-lived resources in the frame graph: the scene's
  // depth-stencil and HDR colour (FrameTargets), and the light buffer.
  ResourceId scene_depth, scene_color, light_buffer;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  float near_plane = 0.05f;
  float far_plane = 200.0f;
  // With the split on (TechniqueOptions::split_lighting), the diffuse and
  // specular light sums a deferred lighting pass writes; invalid otherwise.
  ResourceId diffuse_light{}, specular_light{};
  // The shadow maps (RendererSettings::shadows); invalid while shadows are off.
  ResourceId shadow_atlas{};
  DrawResources draw_buffers{};
};

// The framebuffer of the lit image and the scene's depth-stencil, from the
// graph (a pass that draws into them declares it writes scene_color).
inline GLuint scene_framebuffer(const PassResources& res, const FrameContext& frame) {
  return res.framebuffer({frame.scene_color}, frame.scene_depth);
}
// Where deferred lighting passes draw (shaders/common/lighting_targets.glsl):
// the lit image, and with the split on the diffuse and specular light sums
// as colour attachments 1 and 2; the scene's depth-stencil.
inline GLuint lighting_framebuffer(const PassResources& res, const FrameContext& frame) {
  if (!frame.diffuse_light.valid()) return scene_framebuffer(res, frame);
  return res.framebuffer({frame.scene_color, frame.diffuse_light, frame.specular_light}, frame.scene_depth);
}

// What every pass that shades reads besides its own inputs: the lights and,
// with shadows on, the shadow atlas, which the graph binds at its unit (and
// orders the pass after the shadow maps are drawn, keeping the maps' pass).
inline void read_shading_inputs(PassBuilder& pass, const FrameContext& frame) {
  pass.read(frame.light_buffer, Access::Storage);
  if (frame.shadow_atlas.valid()) pass.sample_at(frame.shadow_atlas, kShadowAtlasUnit);
}

// What every pass that draws the frame's list reads: its instances, their
// slots, materials and indirect commands (so that the graph orders it after
// the pass that culls them, with the barrier indirect draws need).
inline void read_draws(PassBuilder& pass, const FrameContext& frame) {
  if (frame.draw_buffers.commands.valid()) pass.read(frame.draw_buffers.commands, Access::Indirect);
  if (frame.draw_buffers.instances.valid()) pass.read(frame.draw_buffers.instances, Access::Storage);
  if (frame.draw_buffers.slots.valid()) pass.read(frame.draw_buffers.slots, Access::Vertex);
  if (frame.draw_buffers.materials.valid()) pass.read(frame.draw_buffers.materials, Access::Storage);
}

// The shape of the frame's targets (owned by the MeshRenderer). Their GL
// objects are the graph's: a pass reaches them through PassResources and the
// FrameContext's resource handles (scene_framebuffer, lighting_framebuffer).
struct FrameTargets {
  glm::ivec2 size{0};
  int samples = 1;  // MSAA samples of the scene's targets (TechniqueOptions::msaa)
};

}  // namespace atrium::render
