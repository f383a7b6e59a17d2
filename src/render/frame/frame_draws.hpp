// The frame's draws, with one owner: the draw list, the GPU buffers it is
// uploaded to (instances and their slots, materials, indirect commands; on the compute-free
// tier the records' textures and the CPU's commands), and occlusion culling's
// phases, on the GPU or the CPU. Every pass that draws the list finds it bound
// by bind(); the first pass over opaque geometry draws through
// draw_first_pass(), which tests what the last frame hid against the depth that
// pass wrote (render/culling/occlusion_culling.hpp). Reads the registry's
// meshes and the scene's depth; writes the bound buffers.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "ecs/registry.hpp"
#include "gfx/stream_buffer.hpp"
#include "render/culling/gpu_occlusion_culling.hpp"
#include "render/culling/occlusion_culling.hpp"
#include "render/frame/frame_modules.hpp"
#include "render/gpu_assets.hpp"
#include "render/light_buffer.hpp"
#include "render/storage_free.hpp"

namespace atrium::render {

// How a frame culls what it draws (RendererSettings' culling switches, resolved).
struct CullingChoice {
  bool occlusion = false;  // two-phase occlusion culling this frame
  bool on_gpu = false;     // ... with compute shaders (the list holds every in-view command)
};

class FrameDraws {
 public:
  FrameDraws(GpuAssets& gpu, gfx::ShaderLibrary& shaders);

  // Builds the frame's list from the registry (with occlusion culling: what
  // the last frame showed, or on the GPU every command in view), uploads it
  // with the lights of the compute-free tier (`compute_free`), and binds it.
  void begin_frame(ecs::Registry& registry, CullingChoice culling, bool compute_free, std::span<const GpuLight> lights);
  [[nodiscard]] const DrawList& list() const { return list_; }
  // Where the list's commands are drawn from now (FrameContext::commands).
  [[nodiscard]] const CommandSource& commands() const { return source_; }
  [[nodiscard]] bool culled_on_gpu() const { return culling_.on_gpu; }
  // The list's buffers in this frame's graph (FrameContext::draw_buffers),
  // made by begin_frame; none on the compute-free tier.
  [[nodiscard]] DrawResources import_into(FrameGraph& graph) const;

  // Binds the list's buffers (or the tier's textures) again, after a pass that
  // bound its own (the shadow maps), and sets commands() to match.
  void bind();
  // FrameContext::draw_first_pass: draws what the last frame showed, then,
  // once a frame with occlusion culling, what the depth it wrote (`depth`, the
  // scene's depth-stencil texture) does not hide; list() then holds both.
  // Returns the triangles found hidden on the CPU (GPU counts arrive later: take_gpu_counts).
  void draw_first_pass(ecs::Registry& registry, const BatchDrawer& draw, GLuint depth, glm::ivec2 size);
  [[nodiscard]] std::size_t triangles_occluded() const { return triangles_occluded_; }
  [[nodiscard]] std::optional<GpuCullingCounts> take_gpu_counts() { return gpu_culling_.take_counts(); }

  // The "occlusion culling" module (before lighting): with GPU culling, the
  // pass that tests the list's commands before anything draws them (it
  // writes FrameContext::draw_buffers.commands, which every drawing pass reads).
  [[nodiscard]] FrameModule occlusion_module();

 private:
  void upload(const DrawList& list);

  GpuAssets& gpu_;
  DrawList list_;
  CullingChoice culling_;
  bool compute_free_ = false;
  bool occlusion_pending_ = false;  // list_ holds only what the last frame showed; draw_first_pass tests the rest
  std::size_t triangles_occluded_ = 0;
  gfx::StreamBuffer instances_, slots_, materials_, commands_;
  StorageFreeRecords storage_free_;  // the compute-free tier's lights, instances and materials
  DepthReader depth_reader_;
  GpuOcclusionCulling gpu_culling_;
  // The GPU culling phase whose commands passes draw list_ from; none: the uploaded commands.
  std::optional<GpuOcclusionCulling::Phase> active_phase_;
  CommandSource source_;  // what bind() bound
};

}  // namespace atrium::render
