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
#include "render/frame/frame_uniforms.hpp"
#include "render/light_buffer.hpp"
#include "render/lighting/light_sums_pass.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/lighting/shading_model.hpp"
#include "render/output/present_pass.hpp"
#include "render/shadows/shadow_pass.hpp"
#include "render/storage_free.hpp"

namespace atrium::render {
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
void target_defines(const GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
  if (inputs.split_lighting) defines.push_back({"SPLIT_LIGHTING"});
  const int samples = inputs.settings.technique_options.msaa;
  if (samples > 1) defines.push_back({"MSAA_SAMPLES", std::to_string(samples)});
}

// Every define shaders are compiled with, each row from the part that needs it
// (render/shader_globals.hpp), in the order the programs' cache keys list them.
constexpr GlobalDefineRow kGlobalDefines[] = {&lighting::shading_model_defines, &DebugViews::counting_defines,
                                                      &lighting::GBuffer::layout_defines, &target_defines,
                                                      &shadows::ShadowAtlas::shadow_defines, &storage_defines};

}  // namespace

MeshRenderer::MeshRenderer(GpuAssets& gpu)
    : frame_uniforms_(gfx::create_buffer()),
      gpu_(gpu),
      draws_(gpu, gpu.shaders()),
      shadows_(gpu),
      debug_(gpu),
      tonemap_(gpu.shaders()),
      loop_limit_(gfx::shader_loop_limit()) {
  glNamedBufferStorage(frame_uniforms_.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
  // The renderer's own modules, in stage order; the technique is the lighting stage.
  modules_ = {draws_.occlusion_module(),
              shadows::shadow_module(shadows_, draws_),
              debug_.counters_module(),
              lighting::light_sums_module(),
              {FrameStage::Lighting, "technique",
               [this](FrameBuild& build) { technique_->add_passes(build.graph, build.frame, build.targets); }, {}},
              tonemap_.module(),
              debug_.view_module(),
              present_module()};
}

MeshRenderer::~MeshRenderer() = default;

void MeshRenderer::resize(ecs::Registry& registry, glm::ivec2 size) {
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
  output_color_ = gfx::create_render_target(GL_RGBA8, size.x, size.y);
  update_split_targets();
  graph_.forget_imports();
  if (technique_) technique_->resize(targets());
  invalidate_modules(registry);
}

void MeshRenderer::invalidate_modules(ecs::Registry& registry) {
  for (const FrameModule& module : modules_) {
    if (module.invalidate) module.invalidate();
  }
  if (const auto* systems = registry.try_resource<FrameModules>()) {
    for (const FrameModule& module : systems->modules()) {
      if (module.invalidate) module.invalidate();
    }
  }
}

void MeshRenderer::update_split_targets() {
  if (!split_lighting_ || size_.x <= 0) {
    diffuse_light_ = {};
    specular_light_ = {};
  } else {
    diffuse_light_ = gfx::create_render_target(GL_RGBA16F, size_.x, size_.y, technique_options_.msaa);
    specular_light_ = gfx::create_render_target(GL_RGBA16F, size_.x, size_.y, technique_options_.msaa);
  }
  graph_.forget_imports();
}

FrameTargets MeshRenderer::targets() const { return {size_, technique_options_.msaa}; }

void MeshRenderer::select_technique(const std::string& mode) {
  const techniques::TechniqueInfo* info = techniques::find_technique(mode);
  if (!info) throw std::invalid_argument("unknown mode '" + mode + "'");
  if (const std::string why = techniques::refusal(*info, technique_options_); !why.empty()) throw gfx::ResourceLimitError(why);
  technique_.reset();  // release the old technique's targets before the new one allocates
  technique_ = info->create(gpu_, technique_options_);
  technique_->resize(targets());
  mode_ = mode;
}

void MeshRenderer::recreate_technique() {
  technique_.reset();
  reload_pending_ = true;
}

void MeshRenderer::refuse_unbounded_loops(const DrawList& draws, std::uint32_t light_count) const {
  if (!loop_limit_ || light_count <= loop_limit_) return;
  const techniques::LightLoops loops = techniques::find_technique(mode_)->loops_over_every_light;
  const std::string why = loops.opaque                             ? "each pixel loops over every light"
                          : loops.blended && !draws.blended.empty() ? "the scene's blended surfaces are shaded forward over every light"
                                                                    : "";
  if (why.empty()) return;
  throw gfx::ResourceLimitError(mode_ + " with " + std::to_string(light_count) + " lights: " + why +
                                ", and this driver ends a shader's loops after " + std::to_string(loop_limit_) +
                                " iterations (llvmpipe), so pixels would leave lights out; use at most " + std::to_string(loop_limit_) +
                                " lights here" + (draws.blended.empty() ? ", or a tiled, clustered or light-volumes mode" : ", or a tiled or clustered mode"));
}

DebugViewNeeds MeshRenderer::apply_settings(ecs::Registry& registry, const RendererSettings& settings) {
  // A named view says what it needs before the frame is drawn; a view of a
  // resource by its name needs nothing (it is checked once the graph is built).
  const DebugViewNeeds needs = DebugViewModule::needs(settings.debug_view);
  // Refused before any program is compiled for them: a context without image
  // atomics or multisampled textures could not compile those programs.
  if (settings.technique_options.compute_free && (needs.count_lights || needs.count_fragments)) {
    throw gfx::ResourceLimitError("the debug view " + settings.debug_view +
                                  " on the compute-free tier: it counts with image atomics, which this tier lacks");
  }
  require_msaa(settings.technique_options.msaa);
  const bool split_lighting = settings.technique_options.split_lighting || needs.split_lighting;
  std::vector<gfx::ShaderDefine> globals;
  for (const GlobalDefineRow row : kGlobalDefines) row({settings, needs.count_lights, needs.count_fragments, split_lighting}, globals);
  if (reload_pending_) {
    reload_pending_ = false;
    invalidate_modules(registry);
  }
  if (globals == globals_ && settings.technique_options == technique_options_) return needs;
  gpu_.shaders().set_global_defines(globals);
  globals_ = std::move(globals);
  // Every target is remade with the new sample count.
  if (settings.technique_options.msaa != technique_options_.msaa) size_ = glm::ivec2(0);
  technique_options_ = settings.technique_options;
  if (split_lighting != split_lighting_) {
    split_lighting_ = split_lighting;
    update_split_targets();
  }
  // Their programs were compiled with the old globals, their targets in the old layout.
  technique_.reset();
  invalidate_modules(registry);
  return needs;
}

void MeshRenderer::begin_frame(ecs::Registry& registry, const RendererSettings& settings, LightBuffer& lights) {
  const auto& view = registry.resource<ViewState>();
  const auto& scene = registry.resource<SceneSettings>();
  // Both culling paths test with compute shaders: the compute-free tier draws what is in view.
  CullingChoice culling;
  culling.occlusion = settings.frustum_culling && settings.occlusion_culling && !technique_options_.compute_free;
  const CullingDevice device = settings.culling_device != CullingDevice::Automatic ? settings.culling_device
                               : gfx::is_software_renderer()                        ? CullingDevice::Cpu
                                                                                    : CullingDevice::Gpu;
  culling.on_gpu = culling.occlusion && device == CullingDevice::Gpu;
  frame_stats_ = {};
  frame_stats_.lights = lights.count;
  frame_stats_.culled_on_gpu = culling.on_gpu;
  frame_stats_.lighting_stage = lighting::resolve_lighting_stage(technique_options_);
  if (const auto* counts = registry.try_resource<CullingStats>()) {
    frame_stats_.objects = counts->objects;
    frame_stats_.objects_drawn = counts->objects_visible;
  }

  FrameUniforms uniforms{};
  uniforms.view = view.view;
  uniforms.projection = view.projection;
  uniforms.view_projection = view.view_projection;
  uniforms.inverse_view_projection = glm::inverse(view.view_projection);
  uniforms.camera_position = glm::vec4(view.camera_position, 1.0f);
  uniforms.ambient = glm::vec4(scene.ambient, 0.0f);
  uniforms.background = glm::vec4(scene.background, 1.0f);
  uniforms.viewport_size = glm::vec2(size_);
  uniforms.exposure = scene.exposure;
  uniforms.light_count = lights.count;
  planes_ = {view.near_plane, view.far_plane};
  uniforms.near_plane = view.near_plane;
  uniforms.far_plane = view.far_plane;
  glNamedBufferSubData(frame_uniforms_.id(), 0, sizeof(uniforms), &uniforms);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameUniformBinding, frame_uniforms_.id());
  if (!technique_options_.compute_free) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLightStorageBinding, lights.buffer.id());
  // Chooses the shadowed lights and moves them to the front of the light
  // buffer, before anything reads it; their maps are drawn by the graph.
  shadows_.set_compute_free(technique_options_.compute_free);
  (void)shadows_.update(registry, lights, view, size_, settings.shadows, settings.redraw_shadows);
  frame_stats_.shadows = shadows_.stats();
  draws_.begin_frame(registry, culling, technique_options_.compute_free,
                     std::span<const GpuLight>(lights.staging.data(), std::min<std::size_t>(lights.count, lights.staging.size())));
  refuse_unbounded_loops(draws_.list(), lights.count);
}

FrameContext MeshRenderer::import_targets(ecs::Registry& registry, const LightBuffer& lights) {
  const int samples = technique_options_.msaa;
  const auto& view = registry.resource<ViewState>();
  graph_.import_texture("output", output_color_.id(), {GL_RGBA8, size_, 1});
  const ResourceId depth = graph_.import_texture("depth", depth_stencil_.id(), {gfx::kDepthStencilFormat, size_, samples}, ViewKind::Depth);
  FrameContext frame{draws_,
                     [this, &registry, depth](const PassResources& res, const BatchDrawer& draw) {
                       draws_.draw_first_pass(registry, draw, res.texture(depth), size_);
                     },
                     gpu_,
                     lights.staging,
                     registry.resource<SceneSettings>().background,
                     depth,
                     graph_.import_texture("hdr", hdr_color_.id(), {GL_RGBA16F, size_, samples}, ViewKind::Color),
                     graph_.import_buffer("lights", lights.buffer.id(), {static_cast<std::size_t>(lights.count) * sizeof(GpuLight)}),
                     view.view,
                     view.projection,
                     view.near_plane,
                     view.far_plane};
  frame.draw_buffers = draws_.import_into(graph_);
  if (split_lighting_) {
    frame.diffuse_light = graph_.import_texture("diffuse-light", diffuse_light_.id(), {GL_RGBA16F, size_, samples}, ViewKind::Color);
    frame.specular_light = graph_.import_texture("specular-light", specular_light_.id(), {GL_RGBA16F, size_, samples}, ViewKind::Color);
  }
  if (shadows_.texture() != 0 && registry.resource<RendererSettings>().shadows > 0) {
    frame.shadow_atlas = graph_.import_texture("shadow-atlas", shadows_.texture(),
                                               {shadows::ShadowAtlas::kAtlasFormat, glm::ivec2(frame_stats_.shadows.atlas_size), 1},
                                               ViewKind::ShadowAtlas);
  }
  return frame;
}

void MeshRenderer::add_modules(FrameBuild& build) {
  const auto* systems = build.registry.try_resource<FrameModules>();
  for (std::size_t stage = 0; stage < kFrameStageNames.size(); ++stage) {
    const auto in_stage = [&](const FrameModule& module) { return module.stage == static_cast<FrameStage>(stage); };
    for (const FrameModule& module : modules_) {
      if (in_stage(module)) module.add_passes(build);
    }
    if (!systems) continue;
    for (const FrameModule& module : systems->modules()) {
      if (in_stage(module)) module.add_passes(build);
    }
  }
}

void MeshRenderer::render(ecs::Registry& registry) {
  const glm::ivec2 size = registry.resource<Viewport>().size;
  if (size.x <= 0 || size.y <= 0) return;  // a minimised window draws nothing
  // Before the frame's first upload: what it refills, the GPU is done reading.
  pacer_.begin_frame();
  const std::uint64_t waits_at_start = gfx::gpu_waits();
  gfx::use_depth_convention();
  const auto& settings = registry.resource<RendererSettings>();
  const DebugViewNeeds needs = apply_settings(registry, settings);
  if (size != size_) resize(registry, size);
  if (!technique_ || settings.mode != mode_) select_technique(settings.mode);
  auto& lights = registry.resource<LightBuffer>();
  begin_frame(registry, settings, lights);

  graph_.reset();
  graph_.set_poison(settings.poison_targets);
  const FrameContext frame = import_targets(registry, lights);
  const FrameTargets frame_targets = targets();
  FrameBuild build{graph_, registry, frame, frame_targets, frame.scene_color, graph_.find("output")};
  add_modules(build);
  graph_.compile();

  counted_lights_ = needs.count_lights;
  counted_fragments_ = needs.count_fragments;
  timer_.begin_frame();
  try {
    graph_.execute(&timer_);
    // The shadow pass counts its triangles as it draws, after update().
    frame_stats_.shadows = shadows_.stats();
    // The list as the first pass left it (what the passes after it drew).
    frame_stats_.draw_calls = draws_.list().draw_calls();
    frame_stats_.triangles = draws_.list().triangles;
    frame_stats_.triangles_drawn = draws_.list().triangles_drawn;
    frame_stats_.triangles_occluded = draws_.triangles_occluded();
    take_reports(frame_stats_);
  } catch (const gfx::ResourceLimitError& e) {
    throw gfx::ResourceLimitError(mode_ + " with " + std::to_string(lights.count) + " lights at " + std::to_string(size.x) + "x" +
                                  std::to_string(size.y) + ": " + e.what());
  }
  timer_.end_frame();
  pacer_.end_frame();
  frame_stats_.gpu_waits = static_cast<std::uint32_t>(gfx::gpu_waits() - waits_at_start);
  frame_stats_.paced_ms = pacer_.waited_ms();
  stats_ = frame_stats_;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool MeshRenderer::offers(std::string_view view) const {
  const std::vector<OfferedView>& offered = offered_views();
  return std::any_of(offered.begin(), offered.end(), [&](const OfferedView& v) { return v.name == view; });
}

void MeshRenderer::settle() {
  gfx::finish();
  timer_.wait_for_latest();
  take_reports(stats_);
}

void MeshRenderer::take_reports(FrameStats& stats) {
  for (const DebugViews::CountAverage& average : debug_.take_averages()) {
    (average.fragments ? fragment_average_ : light_average_) = average.per_pixel;
  }
  if (counted_lights_) stats.light_evaluations_per_pixel = light_average_;
  if (counted_fragments_) stats.fragments_per_pixel = fragment_average_;
  if (stats.culled_on_gpu) {
    // Until the first counts arrive: everything in view, nothing hidden.
    if (const auto counts = draws_.take_gpu_counts()) {
      stats.triangles_drawn = counts->triangles_drawn;
      stats.triangles_occluded = counts->triangles_hidden;
    }
  }
  if (!technique_) return;
  const techniques::LightingTechnique::ListStats lists = technique_->light_lists();
  stats.light_list_entries = lists.entries;
  stats.light_list_overflows = lists.overflowed_frames;
  stats.light_assignment = lists.assignment;
  stats.light_list_density = lists.density;
  stats.technique_variant = technique_->variant();
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

}  // namespace atrium::render
