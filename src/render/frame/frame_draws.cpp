#include "render/frame/frame_draws.hpp"

#include "assets/asset_manager.hpp"
#include "components/frame_resources.hpp"
#include "gfx/pass_timer.hpp"

namespace atrium::render {

FrameDraws::FrameDraws(GpuAssets& gpu, gfx::ShaderLibrary& shaders) : gpu_(gpu), depth_reader_(shaders), gpu_culling_(shaders) {}

void FrameDraws::begin_frame(ecs::Registry& registry, CullingChoice culling, bool compute_free, std::span<const GpuLight> lights) {
  culling_ = culling;
  compute_free_ = compute_free;
  occlusion_pending_ = culling.occlusion;
  triangles_occluded_ = 0;
  const auto& view = registry.resource<ViewState>();
  list_ = build_draw_list(registry, registry.resource<assets::AssetManager>(), gpu_, view.view,
                          culling.on_gpu      ? DrawSelection::EachInView
                          : culling.occlusion ? DrawSelection::ShownLastFrame
                                              : DrawSelection::InView);
  if (compute_free) storage_free_.upload(lights, list_);
  upload(list_);
}

void FrameDraws::upload(const DrawList& list) {
  // The compute-free tier's records went to textures (StorageFreeRecords) and its commands stay on the CPU.
  if (!compute_free_) {
    instances_.upload(list.instances.data(), list.instances.size() * sizeof(InstanceData));
    slots_.upload(list.slots.data(), list.slots.size() * sizeof(InstanceSlot));
    materials_.upload(list.materials.data(), list.materials.size() * sizeof(MaterialData));
    commands_.upload(list.commands.data(), list.commands.size() * sizeof(DrawCommand));
  }
  active_phase_.reset();
  bind();
}

void FrameDraws::bind() {
  if (compute_free_) {
    // The tier's twins: records in textures, commands drawn from the CPU; no storage or indirect buffer.
    storage_free_.bind();
    source_ = {list_.commands, -1};
    return;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceStorageBinding, instances_.buffer.id());
  gpu_.use_slots(slots_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialStorageBinding, materials_.buffer.id());
  if (active_phase_) {
    source_ = {{}, gpu_culling_.bind(*active_phase_)};
  } else {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.buffer.id());
    source_ = {};
  }
}

DrawResources FrameDraws::import_into(FrameGraph& graph) const {
  if (compute_free_) return {};
  // As allocated: with occlusion culling on the CPU the first pass uploads
  // more into them (what it reveals), within what earlier frames needed.
  return {graph.import_buffer("draw-instances", instances_.buffer.id(), {instances_.capacity}),
          graph.import_buffer("draw-slots", slots_.buffer.id(), {slots_.capacity}),
          graph.import_buffer("draw-materials", materials_.buffer.id(), {materials_.capacity}),
          graph.import_buffer("draw-commands", commands_.buffer.id(), {commands_.capacity})};
}

void FrameDraws::draw_first_pass(ecs::Registry& registry, const BatchDrawer& draw, GLuint depth, glm::ivec2 size) {
  {
    const gfx::PassTimer::Step step("first draws");
    draw(list_.opaque, source_);
  }
  // Once a frame: a debug view's own geometry pass draws the list as it stands.
  if (!occlusion_pending_) return;
  occlusion_pending_ = false;
  if (culling_.on_gpu) {
    // The same phases on the GPU: the revealed commands, then the shown ones
    // for every pass after this one.
    {
      const gfx::PassTimer::Step step("reveal");
      gpu_culling_.reveal(depth, size);
    }
    {
      const gfx::PassTimer::Step step("revealed draws");
      draw(list_.opaque, {{}, gpu_culling_.bind(GpuOcclusionCulling::Phase::Revealed)});
    }
    if (registry.resource<ViewState>().cut) {
      const gfx::PassTimer::Step step("remember");
      gpu_culling_.remember(depth, size);
    }
    active_phase_ = GpuOcclusionCulling::Phase::Shown;
    bind();
    return;
  }
  // On the CPU, under the GPU path's step names: the depth read back and
  // tested, the revealed draws with the lists they need, and in the frame of
  // a cut the completed depth read and tested again.
  const auto& view = registry.resource<ViewState>();
  std::size_t revealed = 0;
  {
    const gfx::PassTimer::Step step("reveal");
    revealed = reveal_unhidden(registry, depth_reader_.read(depth, size), view);
  }
  if (revealed > 0) {
    const gfx::PassTimer::Step step("revealed draws");
    const auto& assets = registry.resource<assets::AssetManager>();
    const DrawList revealed_list = build_draw_list(registry, assets, gpu_, view.view, DrawSelection::Revealed);
    upload(revealed_list);
    draw(revealed_list.opaque, source_);
    list_ = build_draw_list(registry, assets, gpu_, view.view, DrawSelection::Shown);
    upload(list_);
  }
  if (revealed == 0 || !view.cut) {
    triangles_occluded_ = remember_shown(registry, view, nullptr);
    return;
  }
  const gfx::PassTimer::Step step("remember");
  const DepthPyramid full_depth = depth_reader_.read(depth, size);
  triangles_occluded_ = remember_shown(registry, view, &full_depth);
}

FrameModule FrameDraws::occlusion_module() {
  return {FrameStage::BeforeLighting, "occlusion culling", [this](FrameBuild& build) {
            if (!culling_.on_gpu) return;
            // Before anything draws the list: what the last frame showed.
            // It writes the commands the passes after it draw (GpuOcclusionCulling's
            // phases, bound by bind()) from the uploaded ones.
            const ResourceId commands = build.frame.draw_buffers.commands;
            build.graph.add_pass("occlusion culling", [commands](PassBuilder& pass) { pass.write(commands, Access::Storage); },
                                 [this](const PassResources&) {
              gpu_culling_.begin(list_, commands_.buffer.id());
              active_phase_ = GpuOcclusionCulling::Phase::First;
              bind();
            });
          }, {}};
}

}  // namespace atrium::render
