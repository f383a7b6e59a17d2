#include "render/binding_slots.hpp"
#include "render/techniques/tiled/tiled.hpp"

#include "gfx/depth.hpp"
#include "gfx/pass_timer.hpp"
#include "render/frame/scene_passes.hpp"
#include "render/lighting/cpu_light_lists.hpp"

namespace atrium::techniques {
namespace {
constexpr GLuint kTileBoundsBinding = render::kBinBoundsBinding;
}  // namespace

TiledTechnique::TiledTechnique(render::GpuAssets& gpu, const TechniqueOptions& options)
    : compute_free_(options.compute_free),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      bounds_(compute_free_ ? nullptr : &gpu.shaders().get({"tiled/tile_bounds.comp"})),
      assign_(compute_free_ ? std::nullopt : std::optional<lighting::LightAssignmentPrograms>(lighting::LightIndexList::programs(gpu.shaders(), "tiled/assign.comp", options.light_assignment))),
      lighting_(gpu.shaders(), "tiled/lighting", {}, options),
      blended_depth_(gpu.shaders().get({"common/mesh.vert", "common/depth_only.frag"}, {{"POSITION_ONLY"}})),
      blended_bounds_(compute_free_ ? nullptr : &gpu.shaders().get({"tiled/tile_bounds.comp"}, {{"BLENDED"}})),
      blended_(gpu.shaders().get({"common/mesh.vert", "tiled/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa, lighting::lighting_edge_marks(options)) {}

void TiledTechnique::resize(const render::FrameTargets& targets) {
  tiles_ = (glm::uvec2(targets.size) + glm::uvec2(kTileSize - 1)) / glm::uvec2(kTileSize);
  list_ = std::make_unique<lighting::LightIndexList>(glm::uvec3(tiles_, 1));
  blended_list_ = std::make_unique<lighting::LightIndexList>(glm::uvec3(tiles_, 1));
  tile_bounds_ = gfx::create_buffer();
  glNamedBufferStorage(tile_bounds_.id(), static_cast<GLsizeiptr>(std::size_t{tiles_.x} * tiles_.y * sizeof(TileBounds)), nullptr, 0);
  blended_.set("u_tiles", tiles_);
  if (!compute_free_) {
    for (gfx::ShaderProgram* program : {bounds_, blended_bounds_, &assign_->scatter, &assign_->scatter_large, &assign_->gather}) program->set("u_tiles", tiles_);
  }
  lighting_.each([&](gfx::ShaderProgram& p) { p.set("u_tiles", tiles_); });
}

void TiledTechnique::assign_lights(lighting::LightIndexList& list, gfx::ShaderProgram& bounds, std::uint32_t light_count) {
  {
    const gfx::PassTimer::Step step("bounds");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileBoundsBinding, tile_bounds_.id());
    bounds.use();
    glDispatchCompute(tiles_.x, tiles_.y, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  list.assign(light_count, *assign_, [&] { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileBoundsBinding, tile_bounds_.id()); });
}

void TiledTechnique::bin_on_cpu(const render::FrameContext& frame, const render::FrameTargets& targets) {
  cpu_lists_.upload(
      lighting::bin_lights_in_tiles(frame.lights, frame.view, frame.projection, targets.size, kTileSize, frame.near_plane, frame.far_plane));
}

void TiledTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  render::add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  if (compute_free_) {
    const render::ResourceId lists = list_->import_into(graph, "tile-light-lists");
    graph.add_pass("light culling", [&](render::PassBuilder& pass) { pass.write(lists, render::Access::Transfer); },
                   [this, &frame, &targets](const render::PassResources&) { bin_on_cpu(frame, targets); });
    graph.add_pass("lighting", [&](render::PassBuilder& pass) {
      lighting_.declare(pass, gbuffer_, frame);
      pass.read(lists, render::Access::Sampled);
    }, [this, &frame, &targets](const render::PassResources& res) {
      cpu_lists_.bind();
      lighting_.run(res, gbuffer_, frame, targets);
    });
    render::add_transparency_pass(graph, blended_, frame, targets, [&](render::PassBuilder& pass) { pass.read(lists, render::Access::Sampled); },
                          [this] { cpu_lists_.bind(); });
    return;
  }
  const render::ResourceId lists = list_->import_into(graph, "tile-light-lists", render::ViewKind::LightBins);
  graph.publish(lighting::LightBins{lighting::LightBins::Binning::Tiles, lists, tiles_, static_cast<std::uint32_t>(kTileSize), list_.get(), 0});
  graph.add_pass("light culling", [&](render::PassBuilder& pass) {
    gbuffer_.read_targets(pass);
    pass.read(frame.light_buffer, render::Access::Storage);
    pass.write(lists, render::Access::Storage);
  }, [this, &frame](const render::PassResources& res) {
    gbuffer_.bind_textures(res);
    assign_lights(*list_, *bounds_, static_cast<std::uint32_t>(frame.lights.size()));
  });
  graph.add_pass("lighting", [&](render::PassBuilder& pass) {
    lighting_.declare(pass, gbuffer_, frame);
    pass.read(lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) {
    list_->bind();
    lighting_.run(res, gbuffer_, frame, targets);
  });
  blended_listed_ = !frame.draws.list().blended.empty();
  if (!blended_listed_) return;
  const render::ResourceId blended_lists = blended_list_->import_into(graph, "blended-tile-light-lists");
  graph.add_pass("blended light culling", [&](render::PassBuilder& pass) {
    pass.read(frame.scene_depth, render::Access::Transfer);
    pass.read(frame.light_buffer, render::Access::Storage);
    render::read_draws(pass, frame);
    front_depth_ = pass.create("blended-front-depth", render::TextureDesc{gfx::kDepthStencilFormat, targets.size, targets.samples},
                               render::ViewKind::Depth);
    pass.write(blended_lists, render::Access::Storage);
  }, [this, &frame, &targets](const render::PassResources& res) { cull_for_blended(res, frame, targets); });
  render::add_transparency_pass(graph, blended_, frame, targets, [&](render::PassBuilder& pass) { pass.read(blended_lists, render::Access::Storage); },
                        [this] { blended_list_->bind(); });
}

void TiledTechnique::cull_for_blended(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  {
    const glm::ivec2 size = targets.size;
    const GLuint front_framebuffer = res.framebuffer({}, front_depth_);
    glBlitNamedFramebuffer(render::scene_framebuffer(res, frame), front_framebuffer, 0, 0, size.x, size.y, 0, 0, size.x, size.y,
                           GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, front_framebuffer);
    glViewport(0, 0, size.x, size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthCloser);
    glDepthMask(GL_TRUE);
    blended_depth_.use();
    render::draw_items(frame.draws.list().blended, frame.draws.commands());
    glBindTextureUnit(0, res.texture(frame.scene_depth));
    glBindTextureUnit(1, res.texture(front_depth_));
    assign_lights(*blended_list_, *blended_bounds_, static_cast<std::uint32_t>(frame.lights.size()));
  }
}

LightingTechnique::ListStats TiledTechnique::light_lists() {
  if (compute_free_) return {cpu_lists_.entries(), 0};
  if (!list_) return {};
  list_->poll();
  blended_list_->poll();
  const std::uint32_t blended = blended_listed_ ? blended_list_->last_total() : 0;
  return {list_->last_total() + blended, list_->overflow_frames() + blended_list_->overflow_frames(), list_->last_assignment(),
          list_->last_density()};
}

}  // namespace atrium::techniques
