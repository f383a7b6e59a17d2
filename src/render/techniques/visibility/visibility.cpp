#include "render/techniques/visibility/visibility.hpp"

#include <algorithm>
#include <span>
#include <vector>

#include "gfx/depth.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"
#include "gfx/pass_timer.hpp"
#include "render/frame/frame_draws.hpp"
#include "render/frame/scene_passes.hpp"
#include "render/lighting/lighting_pass.hpp"

namespace atrium::techniques {
namespace {

// With MSAA the geometry pass also writes the shading depth (common/shading_depth.glsl).
std::vector<gfx::ShaderDefine> identifier_defines(bool masked, int samples) {
  std::vector<gfx::ShaderDefine> defines{{"VISIBILITY_ID"}, {masked ? "ALPHA_TEST" : "POSITION_ONLY"}};
  if (samples > 1) defines.push_back({"SHADING_DEPTH"});
  return defines;
}

// Bytes of the Units block for `units`; a scene without meshes binds room
// for one unit that nothing reads.
std::size_t units_bytes(std::size_t units) {
  return sizeof(render::VisibilityUnitsHead) + std::max<std::size_t>(units, 1) * sizeof(render::VisibilityUnit);
}

// material_lists.comp's steps.
constexpr unsigned kRangesStep = 0, kScatterStep = 1;

std::vector<gfx::ShaderDefine> resolve_defines(MaterialBinding binding) {
  return binding == MaterialBinding::Bindless ? std::vector<gfx::ShaderDefine>{{"BINDLESS_TEXTURES"}} : std::vector<gfx::ShaderDefine>{};
}

}  // namespace

MaterialBinding resolve_material_binding(const TechniqueOptions& options) {
  const bool available = !options.compute_free && gfx::gl_features().bindless_textures;
  switch (options.material_binding) {
    case MaterialBinding::Bound: return MaterialBinding::Bound;
    case MaterialBinding::Bindless:
      if (!available) {
        throw gfx::ResourceLimitError("--material-binding bindless needs GL_ARB_bindless_texture, which this context lacks; "
                                      "use --material-binding bound or auto");
      }
      return MaterialBinding::Bindless;
    case MaterialBinding::Automatic: break;
  }
  return available ? MaterialBinding::Bindless : MaterialBinding::Bound;
}

VisibilityTechnique::VisibilityTechnique(render::GpuAssets& gpu, const TechniqueOptions& options)
    : gpu_(gpu),
      binding_(resolve_material_binding(options)),
      identifiers_(gpu.shaders().get({"common/mesh.vert", "visibility/id.frag"}, identifier_defines(false, options.msaa))),
      identifiers_masked_(gpu.shaders().get({"common/mesh.vert", "visibility/id.frag"}, identifier_defines(true, options.msaa))),
      classify_(gpu.shaders().get({"visibility/classify.comp"})),
      lists_(gpu.shaders().get({"visibility/material_lists.comp"})),
      resolve_(gpu.shaders().get({"visibility/resolve.comp"}, resolve_defines(binding_))),
      blended_(gpu.shaders().get({"common/mesh.vert", "clustered/shade.frag"})),
      clusters_(gpu.shaders(), options, lighting::ClusterLights::Positions::Depth) {}

std::string VisibilityTechnique::variant() const {
  return "material binding " + std::string(kMaterialBindingNames[static_cast<std::size_t>(binding_)]);
}

void VisibilityTechnique::resize(const render::FrameTargets& targets) {
  clusters_.resize(targets.size);
  const glm::uvec2 tile(classify_.work_group_size());
  tiles_ = (glm::uvec2(glm::max(targets.size, glm::ivec2(0))) + tile - 1u) / tile;
  samples_ = std::max(targets.samples, 1);
  material_capacity_ = 0;  // the lists are sized by tile count and samples: remade at the next frame
}

std::size_t VisibilityTechnique::tile_slots() const {
  const glm::uvec3 tile(classify_.work_group_size());
  return std::min(material_capacity_, std::size_t{tile.x} * tile.y * static_cast<std::size_t>(samples_));
}

// The lists: 4 bytes for each material each tile can show.
std::size_t VisibilityTechnique::tile_list_bytes() const { return tile_count() * tile_slots() * sizeof(std::uint32_t); }

// Each tile's slots: its count of materials, then the materials.
std::size_t VisibilityTechnique::tile_material_bytes() const { return tile_count() * (tile_slots() + 1) * sizeof(std::uint32_t); }

void VisibilityTechnique::reserve_tiles(std::size_t materials) {
  if (materials <= material_capacity_ && dispatch_) return;
  material_capacity_ = std::max<std::size_t>({materials, 2 * material_capacity_, 16});
  dispatch_ = gfx::create_buffer();
  tile_lists_ = gfx::create_buffer();
  tile_materials_ = gfx::create_buffer();
  glNamedBufferStorage(dispatch_.id(), static_cast<GLsizeiptr>(material_capacity_ * sizeof(MaterialTiles)), nullptr, 0);
  glNamedBufferStorage(tile_lists_.id(), static_cast<GLsizeiptr>(tile_list_bytes()), nullptr, 0);
  glNamedBufferStorage(tile_materials_.id(), static_cast<GLsizeiptr>(tile_material_bytes()), nullptr, 0);
}

void VisibilityTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  if (frame.draws.list().visibility_ids > std::uint64_t{1} << 32) {
    throw gfx::ResourceLimitError("visibility-buffer: the scene has " + std::to_string(frame.draws.list().visibility_ids - 1) +
                                  " triangle instances, more than its 32-bit identifiers can name; use another mode");
  }
  graph.add_pass("visibility", [&](render::PassBuilder& pass) {
    render::read_draws(pass, frame);
    pass.write(frame.scene_depth, render::Access::Attachment);
    identifiers_target_ =
        pass.create(render::kVisibilityIdsTarget, render::TextureDesc{GL_R32UI, targets.size, targets.samples}, render::ViewKind::Identifiers);
    // With MSAA the depth buffer holds each sample's own depth; the resolve
    // shades at the pixel centre, whose depth marks the clusters.
    shading_depth_ = targets.samples > 1
                         ? pass.create("shading-depth", render::TextureDesc{GL_R32F, targets.size, targets.samples}, render::ViewKind::Depth)
                         : render::ResourceId{};
  }, [this, &frame, &targets](const render::PassResources& res) { draw_identifiers(res, frame, targets); });

  const render::ResourceId lists = clusters_.begin_frame(graph, frame);
  const render::ResourceId marked_depth = shading_depth_.valid() ? shading_depth_ : frame.scene_depth;
  graph.add_pass("light assignment", [&](render::PassBuilder& pass) {
    pass.read(marked_depth, render::Access::Sampled);
    pass.read(frame.light_buffer, render::Access::Storage);
    if (!frame.draws.list().blended.empty()) render::read_draws(pass, frame);
    pass.write(lists, render::Access::Storage);
  }, [this, &frame, &targets, marked_depth](const render::PassResources& res) {
    clusters_.assign(res, frame, targets, [&] { glBindTextureUnit(0, res.texture(marked_depth)); });
  });

  auto write_lit = [&frame](render::PassBuilder& pass) {
    pass.write(frame.scene_color, render::Access::Storage);
    for (const render::ResourceId sum : {frame.diffuse_light, frame.specular_light}) {
      if (sum.valid()) pass.write(sum, render::Access::Storage);
    }
  };
  auto resolve_inputs = [&](render::PassBuilder& pass) {
    pass.read(identifiers_target_, render::Access::Sampled);
    render::read_draws(pass, frame);
    render::read_shading_inputs(pass, frame);
    pass.read(lists, render::Access::Storage);
    write_lit(pass);
  };
  if (binding_ == MaterialBinding::Bindless) {
    // The resolve gives empty samples the background itself: no classification.
    graph.add_pass("resolve", resolve_inputs, [this, &frame](const render::PassResources& res) { resolve_bindless(res, frame); });
  } else {
    // As many lists as this frame's materials; a list that occlusion culling's
    // late phase extends with new materials grows them when the pass runs.
    reserve_tiles(frame.draws.list().materials.size());
    const render::ResourceId dispatch = graph.import_buffer("material-dispatch", dispatch_.id(), {material_capacity_ * sizeof(MaterialTiles)});
    const render::ResourceId tile_lists =
        graph.import_buffer("material-tiles", tile_lists_.id(), {tile_list_bytes()});
    const render::ResourceId tile_materials =
        graph.import_buffer("tile-materials", tile_materials_.id(), {tile_material_bytes()});
    graph.add_pass("material classification", [&](render::PassBuilder& pass) {
      pass.read(identifiers_target_, render::Access::Sampled);
      render::read_draws(pass, frame);
      write_lit(pass);
      pass.write(dispatch, render::Access::Storage);
      pass.write(tile_lists, render::Access::Storage);
      pass.write(tile_materials, render::Access::Storage);
    }, [this, &frame](const render::PassResources& res) { classify(res, frame); });
    graph.add_pass("resolve", [&](render::PassBuilder& pass) {
      resolve_inputs(pass);
      pass.read(dispatch, render::Access::Indirect);
      pass.read(tile_lists, render::Access::Storage);
    }, [this, &frame](const render::PassResources& res) { resolve(res, frame); });
  }

  render::add_transparency_pass(graph, blended_, frame, targets, [&](render::PassBuilder& pass) { pass.read(lists, render::Access::Storage); },
                                [this] { clusters_.bind(); });
}

void VisibilityTechnique::draw_identifiers(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  const GLuint framebuffer = shading_depth_.valid() ? res.framebuffer({identifiers_target_, shading_depth_}, frame.scene_depth)
                                                    : res.framebuffer({identifiers_target_}, frame.scene_depth);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  const GLuint none[] = {0, 0, 0, 0};
  glClearNamedFramebufferuiv(framebuffer, GL_COLOR, 0, none);
  if (shading_depth_.valid()) {
    const float far = gfx::kDepthFar;
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 1, &far);
  }
  render::begin_depth(framebuffer);
  frame.draw_first_pass(res, [this](std::span<const render::DrawBatch> batches, const render::CommandSource& source) {
    render::draw_depth(batches, source, identifiers_, identifiers_masked_);
  });
}

void VisibilityTechnique::bind_inputs(const render::PassResources& res, const render::FrameContext& frame) const {
  // The head and this frame's units: what the buffer holds past them is stale.
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, render::kVisibilityUnitsBinding, units_.buffer.id(), 0,
                    static_cast<GLsizeiptr>(units_bytes(unit_count_)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kVertexPoolBinding, gpu_.vertex_pool());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kIndexPoolBinding, gpu_.index_pool());
  if (binding_ == MaterialBinding::Bound) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kMaterialDispatchBinding, dispatch_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kMaterialTilesBinding, tile_lists_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kTileMaterialsBinding, tile_materials_.id());
  }
  glBindTextureUnit(render::kVisibilityUnit, res.texture(identifiers_target_));
  lighting::bind_lit_images(res, frame, GL_WRITE_ONLY);
}

void VisibilityTechnique::upload_units(const render::DrawList& list) {
  unit_count_ = list.visibility_units.size();
  // The head, then the units (Units in visibility.glsl), in room for at least
  // the one unit bind_inputs binds.
  const render::VisibilityUnitsHead head{static_cast<std::uint32_t>(unit_count_)};
  units_.reserve(units_bytes(unit_count_));
  units_.upload({std::as_bytes(std::span(&head, 1)), std::as_bytes(std::span(list.visibility_units))});
}

std::vector<const render::DrawBatch*> VisibilityTechnique::batches_by_material(const render::DrawList& list) {
  std::vector<const render::DrawBatch*> batch_of(list.materials.size(), nullptr);
  for (const render::DrawBatch& batch : list.opaque) {
    for (std::uint32_t c = batch.first_command; c < batch.first_command + batch.command_count; ++c) {
      const std::uint32_t slot = list.commands[c].base_instance;
      if (slot < list.slots.size()) batch_of[list.instances[list.slots[slot].record].material.x] = &batch;
    }
  }
  return batch_of;
}

void VisibilityTechnique::classify(const render::PassResources& res, const render::FrameContext& frame) {
  const render::DrawList& list = frame.draws.list();
  reserve_tiles(list.materials.size());
  upload_units(list);
  // Counts from zero; the ranges step writes the rest of each MaterialTiles.
  glClearNamedBufferData(dispatch_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  bind_inputs(res, frame);
  const auto slots = static_cast<unsigned>(tile_slots());
  {
    const gfx::PassTimer::Step step("count");
    classify_.use();
    classify_.set("u_tile_slots", slots);
    glDispatchCompute(tiles_.x, tiles_.y, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  lists_.use();
  lists_.set("u_tile_slots", slots);
  lists_.set("u_material_count", static_cast<unsigned>(list.materials.size()));
  lists_.set("u_tile_count", static_cast<unsigned>(tile_count()));
  lists_.set("u_tile_columns", tiles_.x);
  {
    const gfx::PassTimer::Step step("ranges");
    lists_.set("u_step", kRangesStep);
    glDispatchCompute(1, 1, 1);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  {
    const gfx::PassTimer::Step step("scatter");
    lists_.set("u_step", kScatterStep);
    const std::size_t group = lists_.work_group_size().x;
    glDispatchCompute(static_cast<GLuint>((tile_count() + group - 1) / group), 1, 1);
  }
}

void VisibilityTechnique::resolve(const render::PassResources& res, const render::FrameContext& frame) const {
  // Each material's textures and samplers, from the batches that draw it.
  const std::vector<const render::DrawBatch*> batch_of = batches_by_material(frame.draws.list());
  clusters_.bind();
  bind_inputs(res, frame);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
  resolve_.use();
  for (std::size_t m = 0; m < batch_of.size(); ++m) {
    if (!batch_of[m]) continue;
    glBindTextures(0, render::kMaterialTextureSlots, batch_of[m]->textures.data());
    glBindSamplers(0, render::kMaterialTextureSlots, batch_of[m]->samplers.data());
    resolve_.set("u_material", static_cast<unsigned>(m));
    glDispatchComputeIndirect(static_cast<GLintptr>(m * sizeof(MaterialTiles)));
  }
  glBindSamplers(0, render::kMaterialTextureSlots, nullptr);
}

void VisibilityTechnique::resolve_bindless(const render::PassResources& res, const render::FrameContext& frame) {
  const render::DrawList& list = frame.draws.list();
  upload_units(list);
  // Each material's handles, from the batch that draws it; a material no batch
  // draws shows on no pixel, and samples the white default if it ever did.
  const std::vector<const render::DrawBatch*> batch_of = batches_by_material(list);
  std::vector<MaterialTextures> table(std::max<std::size_t>(batch_of.size(), 1));
  const GLuint white = gpu_.texture({});
  for (std::size_t m = 0; m < table.size(); ++m) {
    const render::DrawBatch* batch = m < batch_of.size() ? batch_of[m] : nullptr;
    for (std::size_t slot = 0; slot < render::kMaterialTextureSlots; ++slot) {
      table[m].handles[slot] = batch ? gpu_.texture_handle(batch->textures[slot], batch->samplers[slot]) : gpu_.texture_handle(white, 0);
    }
  }
  material_textures_.upload(table.data(), table.size() * sizeof(MaterialTextures));
  clusters_.bind();
  bind_inputs(res, frame);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, render::kMaterialTexturesBinding, material_textures_.buffer.id(), 0,
                    static_cast<GLsizeiptr>(table.size() * sizeof(MaterialTextures)));
  resolve_.use();
  glDispatchCompute(tiles_.x, tiles_.y, 1);
}

}  // namespace atrium::techniques
