#include "render/mesh_renderer.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "components/visibility.hpp"
#include "gfx/depth.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/limits.hpp"
#include "render/contributors.hpp"
#include "render/light_buffer.hpp"
#include "render/storage_free.hpp"
#include "render/debug/debug_views.hpp"
#include "render/frame/frame_uniforms.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/lighting/shading_model.hpp"

namespace atrium {
namespace {

void require_msaa(int samples) {
  if (samples <= gfx::max_msaa_samples()) return;
  throw gfx::ResourceLimitError("MSAA with " + std::to_string(samples) + " samples: this context allows at most " +
                                std::to_string(gfx::max_msaa_samples()) +
                                " (the smallest of GL_MAX_SAMPLES and the colour, depth and integer texture sample limits; "
                                "1 without multisampled textures, as on OpenGL ES 3.0 and WebGL2); use a smaller --msaa");
}

// The SPLIT_LIGHTING and MSAA_SAMPLES rows of the shader globals: the
// renderer's light-sum targets and sample count.
void target_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
  if (inputs.split_lighting) defines.push_back({"SPLIT_LIGHTING"});
  const int samples = inputs.settings.technique_options.msaa;
  if (samples > 1) defines.push_back({"MSAA_SAMPLES", std::to_string(samples)});
}

// Every define shaders are compiled with, each row from the part that needs it
// (render/shader_globals.hpp), in the order the programs' cache keys list them.
constexpr render::GlobalDefineRow kGlobalDefines[] = {&lighting::shading_model_defines, &lighting::DebugViews::counting_defines,
                                                      &lighting::GBuffer::layout_defines, &target_defines,
                                                      &shadows::ShadowAtlas::shadow_defines, &render::storage_defines};

}  // namespace

MeshRenderer::MeshRenderer(assets::GpuAssets& gpu)
    : frame_uniforms_(gfx::create_buffer()),
      shadows_(gpu),
      depth_reader_(gpu.shaders()),
      gpu_culling_(gpu.shaders()),
      empty_vertex_array_(gfx::create_vertex_array()),
      gpu_(gpu),
      tonemap_(&gpu.shaders().get({"post/fullscreen.vert", "post/tonemap.frag"})),
      loop_limit_(gfx::shader_loop_limit()) {
  glNamedBufferStorage(frame_uniforms_.id(), sizeof(lighting::FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::resize(glm::ivec2 size) {
  const glm::ivec2 limit = gfx::max_render_size();
  if (size.x > limit.x || size.y > limit.y) {
    throw gfx::ResourceLimitError(std::to_string(size.x) + "x" + std::to_string(size.y) + " is larger than this context can render (" +
                                  std::to_string(limit.x) + "x" + std::to_string(limit.y) +
                                  ": the smallest of GL_MAX_VIEWPORT_DIMS, GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT, "
                                  "GL_MAX_RENDERBUFFER_SIZE and GL_MAX_TEXTURE_SIZE); use a smaller --size");
  }
  const int samples = technique_options_.msaa;
  require_msaa(samples);
  size_ = size;
  hdr_color_ = gfx::create_render_target(GL_RGBA16F, size.x, size.y, samples);
  depth_stencil_ = gfx::create_render_target(gfx::kDepthStencilFormat, size.x, size.y, samples);
  hdr_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(hdr_framebuffer_.id(), GL_COLOR_ATTACHMENT0, hdr_color_.id(), 0);
  glNamedFramebufferTexture(hdr_framebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil_.id(), 0);
  gfx::require_complete(hdr_framebuffer_.id(), "hdr");
  output_color_ = gfx::create_render_target(GL_RGBA8, size.x, size.y);
  output_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(output_framebuffer_.id(), GL_COLOR_ATTACHMENT0, output_color_.id(), 0);
  gfx::require_complete(output_framebuffer_.id(), "output");
  update_split_targets();
  graph_.forget_imports();
  if (technique_) technique_->resize(targets());
  if (debug_views_) debug_views_->resize(targets());
}

void MeshRenderer::update_split_targets() {
  if (!split_lighting_ || size_.x <= 0) {
    lighting_framebuffer_ = {};
    diffuse_light_ = {};
    specular_light_ = {};
    return;
  }
  diffuse_light_ = gfx::create_render_target(GL_RGBA16F, size_.x, size_.y, technique_options_.msaa);
  specular_light_ = gfx::create_render_target(GL_RGBA16F, size_.x, size_.y, technique_options_.msaa);
  lighting_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(lighting_framebuffer_.id(), GL_COLOR_ATTACHMENT0, hdr_color_.id(), 0);
  glNamedFramebufferTexture(lighting_framebuffer_.id(), GL_COLOR_ATTACHMENT1, diffuse_light_.id(), 0);
  glNamedFramebufferTexture(lighting_framebuffer_.id(), GL_COLOR_ATTACHMENT2, specular_light_.id(), 0);
  glNamedFramebufferTexture(lighting_framebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil_.id(), 0);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(lighting_framebuffer_.id(), 3, buffers);
  gfx::require_complete(lighting_framebuffer_.id(), "lighting (split)");
  graph_.forget_imports();
}

lighting::FrameTargets MeshRenderer::targets() const {
  const bool split = lighting_framebuffer_.id() != 0;
  return {hdr_framebuffer_.id(),
          hdr_color_.id(),
          depth_stencil_.id(),
          size_,
          technique_options_.msaa,
          split ? lighting_framebuffer_.id() : hdr_framebuffer_.id(),
          diffuse_light_.id(),
          specular_light_.id()};
}

void MeshRenderer::select_technique(const std::string& mode) {
  const lighting::TechniqueInfo* info = lighting::find_technique(mode);
  if (!info) throw std::invalid_argument("unknown mode '" + mode + "'");
  technique_.reset();  // release the old technique's targets before the new one allocates
  technique_ = info->create(gpu_, technique_options_);
  technique_->resize(targets());
  mode_ = mode;
}

lighting::DebugViews& MeshRenderer::debug_views() {
  if (!debug_views_) {
    debug_views_ = std::make_unique<lighting::DebugViews>(gpu_, technique_options_);
    debug_views_->resize(targets());
  }
  return *debug_views_;
}

GLuint MeshRenderer::gbuffer_thumbnails() const { return thumbnails_drawn_ && debug_views_ ? debug_views_->thumbnails() : 0; }

glm::ivec2 MeshRenderer::thumbnail_size() const { return debug_views_ ? debug_views_->thumbnail_size() : glm::ivec2(0); }

void MeshRenderer::recreate_technique() {
  technique_.reset();
  debug_views_.reset();
}

void MeshRenderer::refuse_unbounded_loops(const lighting::DrawList& draws, std::uint32_t light_count) const {
  if (!loop_limit_ || light_count <= loop_limit_) return;
  const lighting::LightLoops loops = lighting::find_technique(mode_)->loops_over_every_light;
  const std::string why = loops.opaque                             ? "each pixel loops over every light"
                          : loops.blended && !draws.blended.empty() ? "the scene's blended surfaces are shaded forward over every light"
                                                                    : "";
  if (why.empty()) return;
  throw gfx::ResourceLimitError(mode_ + " with " + std::to_string(light_count) + " lights: " + why +
                                ", and this driver ends a shader's loops after " + std::to_string(loop_limit_) +
                                " iterations (llvmpipe), so pixels would leave lights out; use at most " + std::to_string(loop_limit_) +
                                " lights here" + (draws.blended.empty() ? ", or a tiled, clustered or light-volumes mode" : ", or a tiled or clustered mode"));
}

void MeshRenderer::upload_draws(const lighting::DrawList& draws) {
  gpu_.reserve_instances(draws.instances.size());
  // The compute-free tier's records went to textures (StorageFreeRecords) and its commands stay on the CPU.
  if (!technique_options_.compute_free) {
    instances_.upload(draws.instances.data(), draws.instances.size() * sizeof(lighting::InstanceData));
    materials_.upload(draws.materials.data(), draws.materials.size() * sizeof(lighting::MaterialData));
    commands_.upload(draws.commands.data(), draws.commands.size() * sizeof(lighting::DrawCommand));
  }
  active_phase_.reset();
  bind_draws();
}

void MeshRenderer::bind_draws() const {
  if (technique_options_.compute_free) {
    // The tier's twins: records in textures, commands drawn from the CPU; no storage or indirect buffer.
    storage_free_.bind();
    lighting::draw_commands_from_cpu(draws_.commands);
    lighting::draw_counts_from(-1);
    return;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lighting::kInstanceStorageBinding, instances_.buffer.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lighting::kMaterialStorageBinding, materials_.buffer.id());
  lighting::draw_commands_from_cpu({});
  if (active_phase_) {
    gpu_culling_.bind(*active_phase_);
  } else {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.buffer.id());
    lighting::draw_counts_from(-1);
  }
}

void MeshRenderer::draw_first_pass(ecs::Registry& registry, const lighting::DrawBatches& draw) {
  draw(draws_.opaque);
  // Once a frame: a debug view's own geometry pass draws the list as it stands.
  if (!occlusion_pending_) return;
  occlusion_pending_ = false;
  if (culling_on_gpu_) {
    // The same phases on the GPU: the revealed commands, then the shown ones
    // for every pass after this one.
    gpu_culling_.reveal(depth_stencil_.id(), size_);
    gpu_culling_.bind(GpuOcclusionCulling::Phase::Revealed);
    draw(draws_.opaque);
    gpu_culling_.remember(depth_stencil_.id(), size_);
    active_phase_ = GpuOcclusionCulling::Phase::Shown;
    bind_draws();
    return;
  }
  const auto& view = registry.resource<ViewState>();
  DepthPyramid depth = depth_reader_.read(depth_stencil_.id(), size_);
  const OcclusionCounts late = reveal_unhidden(registry, depth, view);
  if (late.tested > late.hidden) {
    const auto& assets = registry.resource<assets::AssetManager>();
    const lighting::DrawList revealed = lighting::build_draw_list(registry, assets, gpu_, view.view, lighting::DrawSelection::Revealed);
    upload_draws(revealed);
    draw(revealed.opaque);
    draws_ = lighting::build_draw_list(registry, assets, gpu_, view.view, lighting::DrawSelection::Shown);
    upload_draws(draws_);
    depth = depth_reader_.read(depth_stencil_.id(), size_);
  }
  frame_stats_.triangles_occluded = remember_shown(registry, depth, view).triangles_hidden;
}

void MeshRenderer::render(ecs::Registry& registry) {
  const glm::ivec2 size = registry.resource<Viewport>().size;
  if (size.x <= 0 || size.y <= 0) return;  // a minimised window draws nothing
  const std::uint64_t waits_at_start = gfx::gpu_waits();
  gfx::use_depth_convention();
  const auto& settings = registry.resource<RendererSettings>();
  // A named view says what it needs before the frame is drawn; a view of a
  // resource by its name needs nothing (it is checked once the graph is built).
  const lighting::DebugView* named_view = lighting::find_debug_view(settings.debug_view);
  const lighting::DebugViewNeeds needs = named_view ? named_view->needs : lighting::DebugViewNeeds{};
  const bool counting_lights = needs.count_lights;
  const bool counting_fragments = needs.count_fragments;
  const bool counting = counting_lights || counting_fragments;
  const bool split_lighting = settings.technique_options.split_lighting || needs.split_lighting;
  // Refused before any program is compiled for them: a context without image
  // atomics or multisampled textures could not compile those programs.
  if (settings.technique_options.compute_free && counting) {
    throw gfx::ResourceLimitError("the debug view " + settings.debug_view +
                                  " on the compute-free tier: it counts with image atomics, which this tier lacks");
  }
  require_msaa(settings.technique_options.msaa);
  const lighting::LightingStage stage = lighting::resolve_lighting_stage(settings.technique_options);
  std::vector<gfx::ShaderDefine> globals;
  for (const render::GlobalDefineRow row : kGlobalDefines) row({settings, counting_lights, counting_fragments, split_lighting}, globals);
  if (globals != globals_ || settings.technique_options != technique_options_) {
    gpu_.shaders().set_global_defines(globals);
    globals_ = std::move(globals);
    tonemap_ = &gpu_.shaders().get({"post/fullscreen.vert", "post/tonemap.frag"});
    tonemap_compute_ = nullptr;
    // Every target is remade with the new sample count.
    if (settings.technique_options.msaa != technique_options_.msaa) size_ = glm::ivec2(0);
    technique_options_ = settings.technique_options;
    if (split_lighting != split_lighting_) {
      split_lighting_ = split_lighting;
      update_split_targets();
    }
    // Their programs were compiled with the old globals, their G-buffers in the old layout.
    technique_.reset();
    debug_views_.reset();
  }
  if (size != size_) resize(size);
  if (!technique_ || settings.mode != mode_) select_technique(settings.mode);

  const auto& view = registry.resource<ViewState>();
  const auto& scene = registry.resource<SceneSettings>();
  auto& lights = registry.resource<LightBuffer>();
  const auto& assets = registry.resource<assets::AssetManager>();
  const auto& gpu = registry.resource<assets::GpuAssets>();

  // Both culling paths test with compute shaders: the compute-free tier draws what is in view.
  occlusion_pending_ = settings.frustum_culling && settings.occlusion_culling && !technique_options_.compute_free;
  const CullingDevice device = settings.culling_device != CullingDevice::Automatic ? settings.culling_device
                               : gfx::is_software_renderer()                        ? CullingDevice::Cpu
                                                                                    : CullingDevice::Gpu;
  culling_on_gpu_ = occlusion_pending_ && device == CullingDevice::Gpu;
  draws_ = lighting::build_draw_list(registry, assets, gpu, view.view,
                                     culling_on_gpu_     ? lighting::DrawSelection::EachInView
                                     : occlusion_pending_ ? lighting::DrawSelection::ShownLastFrame
                                                          : lighting::DrawSelection::InView);
  const lighting::DrawList& draws = draws_;
  frame_stats_ = {};
  frame_stats_.lights = lights.count;
  frame_stats_.culled_on_gpu = culling_on_gpu_;
  frame_stats_.lighting_stage = stage;
  if (const auto* culling = registry.try_resource<CullingStats>()) {
    frame_stats_.objects = culling->objects;
    frame_stats_.objects_drawn = culling->objects_visible;
  }

  lighting::FrameUniforms uniforms{};
  uniforms.view = view.view;
  uniforms.projection = view.projection;
  uniforms.view_projection = view.view_projection;
  uniforms.inverse_view_projection = glm::inverse(view.view_projection);
  uniforms.camera_position = glm::vec4(view.camera_position, 1.0f);
  uniforms.ambient = glm::vec4(scene.ambient, 0.0f);
  uniforms.background = glm::vec4(scene.background, 1.0f);
  uniforms.viewport_size = glm::vec2(size);
  uniforms.exposure = scene.exposure;
  uniforms.light_count = lights.count;
  planes_ = {view.near_plane, view.far_plane};
  uniforms.near_plane = view.near_plane;
  uniforms.far_plane = view.far_plane;
  glNamedBufferSubData(frame_uniforms_.id(), 0, sizeof(uniforms), &uniforms);
  glBindBufferBase(GL_UNIFORM_BUFFER, lighting::kFrameUniformBinding, frame_uniforms_.id());
  if (!technique_options_.compute_free) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, lighting::kLightStorageBinding, lights.buffer.id());
  // Chooses the shadowed lights and moves them to the front of the light
  // buffer, before anything reads it; their maps are drawn by the graph.
  shadows_.set_compute_free(technique_options_.compute_free);
  const bool draw_shadows = shadows_.update(registry, lights, view, size, settings.shadows, settings.redraw_shadows);
  frame_stats_.shadows = shadows_.stats();
  if (technique_options_.compute_free) {
    storage_free_.upload(std::span<const GpuLight>(lights.staging.data(), std::min<std::size_t>(lights.count, lights.staging.size())), draws);
  }
  upload_draws(draws);
  refuse_unbounded_loops(draws, lights.count);

  // The frame's graph: the renderer's long-lived targets, then each
  // contributor's passes in the order they run.
  graph_.reset();
  const int samples = technique_options_.msaa;
  const render::ResourceId depth = graph_.import_texture("depth", depth_stencil_.id(), {gfx::kDepthStencilFormat, size_, samples}, render::ViewKind::Depth);
  const render::ResourceId hdr = graph_.import_texture("hdr", hdr_color_.id(), {GL_RGBA16F, size_, samples}, render::ViewKind::Color);
  const render::ResourceId output = graph_.import_texture("output", output_color_.id(), {GL_RGBA8, size_, 1});
  const render::ResourceId light_resource =
      graph_.import_buffer("lights", lights.buffer.id(), {static_cast<std::size_t>(lights.count) * sizeof(GpuLight)});
  std::vector<render::ResourceId> light_sums;
  if (split_lighting_) {
    light_sums = {graph_.import_texture("diffuse-light", diffuse_light_.id(), {GL_RGBA16F, size_, samples}, render::ViewKind::Color),
                  graph_.import_texture("specular-light", specular_light_.id(), {GL_RGBA16F, size_, samples}, render::ViewKind::Color)};
  }
  const lighting::FrameContext frame{draws,
                                     [&](const lighting::DrawBatches& draw) { draw_first_pass(registry, draw); },
                                     gpu,
                                     lights.staging,
                                     scene.background,
                                     depth,
                                     hdr,
                                     light_resource,
                                     view.view,
                                     view.projection,
                                     view.near_plane,
                                     view.far_plane,
                                     split_lighting_ ? light_sums[0] : render::ResourceId{},
                                     split_lighting_ ? light_sums[1] : render::ResourceId{}};
  const lighting::FrameTargets frame_targets = targets();

  if (culling_on_gpu_) {
    // Before anything draws the list: what the last frame showed.
    graph_.add_pass("occlusion culling", [](render::PassBuilder& pass) { pass.keep(); }, [&](const render::PassResources&) {
      gpu_culling_.begin(draws_, commands_.buffer.id());
      active_phase_ = GpuOcclusionCulling::Phase::First;
      bind_draws();
    });
  }
  const render::ResourceId atlas =
      shadows_.texture() != 0 && settings.shadows > 0
          ? graph_.import_texture("shadow-atlas", shadows_.texture(), {shadows::ShadowAtlas::kAtlasFormat, glm::ivec2(frame_stats_.shadows.atlas_size), 1},
                                  render::ViewKind::ShadowAtlas)
          : render::ResourceId{};
  if (draw_shadows) {
    graph_.add_pass("shadows", [&](render::PassBuilder& pass) { pass.write(atlas, render::Access::Attachment); },
                    [&](const render::PassResources&) {
                      shadows_.draw_pending(registry);
                      bind_draws();  // the shadow passes bound casters of their own
                    });
  }
  if (counting) debug_views().add_counting_pass(graph_, needs);
  if (split_lighting_) {
    graph_.add_pass("clear light sums", [&](render::PassBuilder& pass) {
      for (const render::ResourceId sum : light_sums) pass.write(sum, render::Access::Transfer);
    }, [&](const render::PassResources&) {
      // Forward modes leave the sums untouched: they show as no light, not a stale frame.
      const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
      glClearNamedFramebufferfv(lighting_framebuffer_.id(), GL_COLOR, 1, zero);
      glClearNamedFramebufferfv(lighting_framebuffer_.id(), GL_COLOR, 2, zero);
    }, false);
  }
  technique_->add_passes(graph_, frame, frame_targets);
  if (const auto* contributors = registry.try_resource<RenderContributors>()) {
    for (const RenderContributor& contributor : contributors->after_lighting) contributor(graph_, registry, frame, frame_targets);
  }

  const bool compute_tonemap = stage == lighting::LightingStage::Compute;
  graph_.add_pass("tonemap", [&](render::PassBuilder& pass) {
    pass.read(hdr, render::Access::Sampled);
    pass.write(output, compute_tonemap ? render::Access::Storage : render::Access::Attachment);
  }, [&](const render::PassResources& res) {
    if (compute_tonemap) {
      if (!tonemap_compute_) tonemap_compute_ = &gpu_.shaders().get({"post/tonemap.comp"});
      glBindTextureUnit(0, res.texture(hdr));
      glBindImageTexture(lighting::kDisplayImageUnit, res.texture(output), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
      lighting::dispatch_per_pixel(*tonemap_compute_, size_);
      return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, output_framebuffer_.id());
    glViewport(0, 0, size_.x, size_.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    tonemap_->use();
    glBindTextureUnit(0, res.texture(hdr));
    glBindVertexArray(empty_vertex_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  });

  // What this frame's graph offers, before any debug view adds to it.
  offered_views_ = lighting::offered_views(graph_, technique_options_);
  std::optional<lighting::SelectedView> debug_view;
  if (!settings.debug_view.empty()) {
    debug_view = lighting::select_view(settings.debug_view, graph_);
    if (!debug_view) {
      std::string names;
      for (const lighting::OfferedView& view : offered_views_) names += (names.empty() ? "" : ", ") + view.name;
      throw lighting::UnknownViewError("unknown debug view '" + settings.debug_view + "' (views: " + names + ")");
    }
  }
  const auto* extent = registry.try_resource<SceneBounds>();
  const lighting::DebugViewFrame view_frame{frame, frame_targets, graph_, extent ? extent->min : glm::vec3(0.0f),
                                            extent ? extent->max : glm::vec3(1.0f)};
  const bool technique_gbuffer = lighting::GBuffer::find(graph_).has_value();
  thumbnails_drawn_ = settings.gbuffer_thumbnails && technique_gbuffer;
  if (thumbnails_drawn_) {
    graph_.add_pass("thumbnails", [&](render::PassBuilder& pass) {
      pass.keep();
      lighting::DebugViews::declare_thumbnail_reads(pass, graph_, frame);
    }, [&](const render::PassResources& res) { debug_views().draw_thumbnails(view_frame, res); }, false);
  }
  if (debug_view) {
    // A G-buffer view in a mode without one fills the views' own.
    if (needs.gbuffer && !technique_gbuffer) debug_views().add_gbuffer_pass(graph_, frame, frame_targets);
    graph_.add_pass("debug view", [&](render::PassBuilder& pass) {
      lighting::DebugViews::declare_reads(*debug_view, pass, graph_, frame);
      pass.write(output, render::Access::Attachment);
    }, [&](const render::PassResources& res) {
      debug_views().draw(*debug_view, view_frame, res, output_framebuffer_.id());
      if (counting) debug_views().send_counts(needs);
    });
  }
  if (settings.present_to_window) {
    graph_.add_pass("present", [&](render::PassBuilder& pass) {
      pass.read(output, render::Access::Transfer);
      pass.keep();
    }, [&](const render::PassResources&) {
      glBlitNamedFramebuffer(output_framebuffer_.id(), 0, 0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }, false);
    if (const auto* contributors = registry.try_resource<RenderContributors>()) {
      for (const RenderContributor& contributor : contributors->on_window) contributor(graph_, registry, frame, frame_targets);
    }
  }

  graph_.compile();
  timer_.begin_frame();
  counted_lights_ = counting_lights;
  counted_fragments_ = counting_fragments;
  try {
    graph_.execute(&timer_);
    // draws_ as the first pass left it (what the passes after it drew).
    frame_stats_.draw_calls = draws.draw_calls();
    frame_stats_.triangles = draws.triangles;
    frame_stats_.triangles_drawn = draws.triangles_drawn;
    take_reports(frame_stats_);
  } catch (const gfx::ResourceLimitError& e) {
    throw gfx::ResourceLimitError(mode_ + " with " + std::to_string(lights.count) + " lights at " + std::to_string(size.x) + "x" +
                                  std::to_string(size.y) + ": " + e.what());
  }
  timer_.end_frame();
  frame_stats_.gpu_waits = static_cast<std::uint32_t>(gfx::gpu_waits() - waits_at_start);
  stats_ = frame_stats_;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool MeshRenderer::offers(std::string_view view) const {
  return std::any_of(offered_views_.begin(), offered_views_.end(), [&](const lighting::OfferedView& v) { return v.name == view; });
}

void MeshRenderer::settle() {
  gfx::finish();
  timer_.wait_for_latest();
  take_reports(stats_);
}

void MeshRenderer::take_reports(FrameStats& stats) {
  if (debug_views_) {
    for (const lighting::DebugViews::CountAverage& average : debug_views_->take_averages()) {
      (average.fragments ? fragment_average_ : light_average_) = average.per_pixel;
    }
  }
  if (counted_lights_) stats.light_evaluations_per_pixel = light_average_;
  if (counted_fragments_) stats.fragments_per_pixel = fragment_average_;
  if (stats.culled_on_gpu) {
    // Until the first counts arrive: everything in view, nothing hidden.
    if (const auto counts = gpu_culling_.take_counts()) {
      stats.triangles_drawn = counts->triangles_drawn;
      stats.triangles_occluded = counts->triangles_hidden;
    }
  }
  if (!technique_) return;
  const lighting::LightingTechnique::ListStats lists = technique_->light_lists();
  stats.light_list_entries = lists.entries;
  stats.light_list_overflows = lists.overflowed_frames;
  stats.light_assignment = lists.assignment;
  stats.light_list_density = lists.density;
}

// Read-backs come after the frame: the compute stage stored its targets with
// imageStore, which copies out of a texture see only after a barrier.
void MeshRenderer::make_shader_writes_readable() const {
  if (gfx::gl_features().memory_barriers) glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

assets::Image MeshRenderer::read_output() const {
  assets::Image image{size_.x, size_.y, std::vector<std::uint8_t>(static_cast<std::size_t>(size_.x) * size_.y * 4)};
  if (image.rgba.empty()) return image;
  make_shader_writes_readable();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gfx::read_texture(output_color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(image.rgba.size()),
                    image.rgba.data());
  // GL's rows run bottom to top; images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(size_.x) * 4;
  for (int y = 0; y < size_.y / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + static_cast<std::ptrdiff_t>(y * row),
                     image.rgba.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                     image.rgba.begin() + static_cast<std::ptrdiff_t>((size_.y - 1 - y) * row));
  }
  return image;
}

gfx::Texture MeshRenderer::resolve(GLuint texture, GLenum format, bool depth) const {
  gfx::Texture resolved = gfx::create_render_target(format, size_.x, size_.y);
  const gfx::Framebuffer from = gfx::create_framebuffer(), to = gfx::create_framebuffer();
  const GLenum attachment = depth ? GL_DEPTH_STENCIL_ATTACHMENT : GL_COLOR_ATTACHMENT0;
  glNamedFramebufferTexture(from.id(), attachment, texture, 0);
  glNamedFramebufferTexture(to.id(), attachment, resolved.id(), 0);
  glBlitNamedFramebuffer(from.id(), to.id(), 0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y,
                         depth ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT, GL_NEAREST);
  return resolved;
}

std::vector<float> MeshRenderer::read_view_depth() const {
  const std::size_t count = static_cast<std::size_t>(size_.x) * size_.y;
  std::vector<float> bottom_up(count);
  if (count == 0) return bottom_up;
  const bool multisampled = technique_options_.msaa > 1;
  const gfx::Texture resolved = multisampled ? resolve(depth_stencil_.id(), gfx::kDepthStencilFormat, true) : gfx::Texture{};
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  gfx::read_texture(multisampled ? resolved.id() : depth_stencil_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(count * sizeof(float)),
                    bottom_up.data());
  std::vector<float> top_down(count);
  for (int y = 0; y < size_.y; ++y) {
    for (int x = 0; x < size_.x; ++x) {
      const float depth = bottom_up[static_cast<std::size_t>(y) * static_cast<std::size_t>(size_.x) + static_cast<std::size_t>(x)];
      top_down[static_cast<std::size_t>(size_.y - 1 - y) * static_cast<std::size_t>(size_.x) + static_cast<std::size_t>(x)] =
          depth <= gfx::kDepthFar ? std::numeric_limits<float>::infinity() : gfx::view_depth_from_depth(depth, planes_.x, planes_.y);
    }
  }
  return top_down;
}

std::vector<glm::vec4> MeshRenderer::read_hdr(HdrTarget target) const {
  const GLuint texture = target == HdrTarget::Color ? hdr_color_.id()
                         : target == HdrTarget::DiffuseLight ? diffuse_light_.id()
                                                             : specular_light_.id();
  if (texture == 0) return {};
  make_shader_writes_readable();
  std::vector<glm::vec4> texels(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
  const bool multisampled = technique_options_.msaa > 1;
  const gfx::Texture resolved = multisampled ? resolve(texture, GL_RGBA16F, false) : gfx::Texture{};
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  gfx::read_texture(multisampled ? resolved.id() : texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
  return texels;
}

void register_mesh_renderer(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::Render, "mesh_renderer",
                [](ecs::Registry& registry) { registry.resource<MeshRenderer>().render(registry); });
}

}  // namespace atrium
