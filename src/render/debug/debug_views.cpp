#include "render/binding_slots.hpp"
#include "render/debug/debug_views.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

#include "render/frame/scene_passes.hpp"

namespace atrium::render {

namespace {


// A resource's visualiser, picked by its ViewKind: what a view of any
// resource of that kind shows, and how it draws it.
struct Visualiser {
  ViewKind kind;
  std::string_view shows;
  void (*draw)(DebugViews& views, ResourceId resource, const DebugViewFrame& frame, const PassResources& res,
               glm::vec2 origin, glm::vec2 scale);
};

constexpr Visualiser kVisualisers[] = {
    {ViewKind::Color, "colour or light, exposed and tone-mapped",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame&, const PassResources& res, glm::vec2 origin,
        glm::vec2 scale) { views.show_light_sum(resource, res, origin, scale); }},
    {ViewKind::Depth, "view depth on a log scale, near white",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
        glm::vec2 scale) { views.show_depth(resource, frame, res, origin, scale); }},
    {ViewKind::Counts, "per-pixel counts as a heatmap",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame& frame, const PassResources& res, glm::vec2,
        glm::vec2) { views.show_counts(resource, frame, res); }},
    {ViewKind::LightBins, "lights in each pixel's bin (magenta: a bin that did not fit this frame)",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame& frame, const PassResources& res, glm::vec2,
        glm::vec2) { views.show_light_bins(resource, frame, res); }},
    {ViewKind::ShadowAtlas, "shadow-map depths",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame&, const PassResources& res, glm::vec2, glm::vec2) {
       views.show_shadow_atlas(resource, res);
     }},
    {ViewKind::Identifiers, "identifiers, a colour each (black: none)",
     [](DebugViews& views, ResourceId resource, const DebugViewFrame&, const PassResources& res, glm::vec2, glm::vec2) {
       views.show_identifiers(resource, res, DebugViews::Identify::Value);
     }},
};

const Visualiser* visualiser_for(ViewKind kind) {
  const auto it = std::find_if(std::begin(kVisualisers), std::end(kVisualisers), [&](const Visualiser& v) { return v.kind == kind; });
  return it == std::end(kVisualisers) ? nullptr : &*it;
}

// The resource a row shows: by name, or the first of the row's kind; invalid
// when the frame has none or the row names none.
ResourceId resource_of(const DebugView& row, const FrameGraph& graph) {
  if (!row.resource.empty()) return graph.find(std::string(row.resource));
  return row.kind == ViewKind::None ? ResourceId{} : graph.first_of(row.kind);
}

bool always(const FrameGraph&, const TechniqueOptions&) { return true; }
bool has_gbuffer(const FrameGraph& graph, const TechniqueOptions&) { return lighting::GBuffer::find(graph).has_value(); }
template <const char* kName>
bool has_resource(const FrameGraph& graph, const TechniqueOptions&) {
  return graph.find(kName).valid();
}
bool has_light_bins(const FrameGraph& graph, const TechniqueOptions&) { return graph.first_of(ViewKind::LightBins).valid(); }
// The modes that shade each pixel once from a G-buffer or the visibility
// buffer: those that can write the light sums apart.
bool shades_pixels_once(const FrameGraph& graph, const TechniqueOptions& options) {
  return has_gbuffer(graph, options) || graph.find(kVisibilityIdsTarget).valid();
}

template <const char* kTarget>
void gbuffer_target(DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin, glm::vec2 scale) {
  views.show_gbuffer(kTarget, frame, res, origin, scale);
}
// Only the passes that shade each pixel once (deferred lighting, the
// visibility buffer's resolve) write the sums apart: a forward mode's stay grey.
template <const char* kName>
void split_sum(DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin, glm::vec2 scale) {
  const ResourceId sum = frame.graph.find(kName);
  if (sum.valid() && shades_pixels_once(frame.graph, {})) views.show_light_sum(sum, res, origin, scale);
  else views.show_nothing();
}
constexpr char kPosition[] = "POSITION", kNormal[] = "NORMAL", kAlbedo[] = "ALBEDO", kMetallicRoughness[] = "METALLIC_ROUGHNESS",
               kEmissive[] = "EMISSIVE";
constexpr char kDiffuseLight[] = "diffuse-light", kSpecularLight[] = "specular-light", kLightBuffer[] = "light-buffer.diffuse",
               kShadowAtlas[] = "shadow-atlas";

// The visibility buffer's identifiers, a colour per triangle, per draw (the
// primitive instance that drew it) or per material (the classification's).
template <DebugViews::Identify kWhat>
void identifiers(DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2, glm::vec2) {
  const ResourceId ids = frame.graph.find(kVisibilityIdsTarget);
  if (ids.valid()) views.show_identifiers(ids, res, kWhat);
  else views.show_nothing();
}

constexpr DebugViewNeeds kGBuffer{.gbuffer = true};

const std::array kViews{
    DebugView{"position", "world position, scaled to the scene's bounds", kGBuffer, {}, {}, always, gbuffer_target<kPosition>},
    DebugView{"normal", "shading normal (normal maps applied)", kGBuffer, {}, {}, always, gbuffer_target<kNormal>},
    DebugView{"albedo", "base colour (grey in the light pre-pass's thin G-buffer, which has none)", kGBuffer, {}, {}, always,
              gbuffer_target<kAlbedo>},
    DebugView{"metallic-roughness", "metallic in red, roughness in green", kGBuffer, {}, {}, always, gbuffer_target<kMetallicRoughness>},
    DebugView{"emissive", "emitted light, tone-mapped", kGBuffer, {}, {}, always, gbuffer_target<kEmissive>},
    DebugView{"depth", "view depth on a log scale, near white", {}, "depth", {}, always},
    DebugView{"light-volumes", "outlines of the light spheres over the lit image", kGBuffer, {}, {}, always,
              [](DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2, glm::vec2) {
                views.show_over_gbuffer("debug/outlines.frag", frame, res, false);
              }},
    DebugView{"heatmap", "lights evaluated per pixel by the mode", {.count_lights = true}, "light-counts", {}, always},
    DebugView{"light-lists", "lights in each pixel's tile or cluster list (magenta: a bin that did not fit this frame)", {}, {},
              ViewKind::LightBins, has_light_bins},
    DebugView{"depth-slices", "the cluster depth slices (--cluster-grid, --z-slicing)", {}, {}, {}, always,
              [](DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2, glm::vec2) {
                views.show_depth_slices(frame, res);
              }},
    DebugView{"fragments", "fragments the geometry passes rasterise per pixel (overdraw)", {.count_fragments = true}, "fragment-counts",
              {}, always},
    DebugView{"diffuse-light", "the diffuse light sum, apart (deferred modes, visibility-buffer)", {.split_lighting = true}, kDiffuseLight,
              {}, shades_pixels_once, split_sum<kDiffuseLight>},
    DebugView{"specular-light", "the specular light sum, apart (deferred modes, visibility-buffer)", {.split_lighting = true},
              kSpecularLight, {}, shades_pixels_once, split_sum<kSpecularLight>},
    DebugView{"light-buffer", "light summed before materials (light-prepass)", {}, kLightBuffer, {}, has_resource<kLightBuffer>},
    DebugView{"msaa-edges", "the pixels the deferred modes shade per sample, in red (with --msaa)", kGBuffer, {}, {},
              [](const FrameGraph& graph, const TechniqueOptions& options) { return options.msaa > 1 && has_gbuffer(graph, options); },
              [](DebugViews& views, const DebugViewFrame& frame, const PassResources& res, glm::vec2, glm::vec2) {
                views.show_over_gbuffer("debug/msaa_edges.frag", frame, res, true);
              }},
    DebugView{"shadow-atlas", "the shadow maps' depths (with --shadows)", {}, kShadowAtlas, {}, has_resource<kShadowAtlas>},
    DebugView{"triangles", "the triangle each pixel shows, a colour each (visibility-buffer)", {}, kVisibilityIdsTarget, {},
              has_resource<kVisibilityIdsTarget>, identifiers<DebugViews::Identify::Value>},
    DebugView{"draws", "the primitive instance each pixel shows, a colour each (visibility-buffer)", {}, kVisibilityIdsTarget, {},
              has_resource<kVisibilityIdsTarget>, identifiers<DebugViews::Identify::Draw>},
    DebugView{"materials", "the material each pixel is shaded with, a colour each: what the bound resolve's classification sorts tiles by (visibility-buffer)", {},
              kVisibilityIdsTarget, {}, has_resource<kVisibilityIdsTarget>, identifiers<DebugViews::Identify::Material>},
    DebugView{"msaa-surfaces", "the pixels whose samples show two surfaces or more, each shaded apart, in red (visibility-buffer, with --msaa)",
              {}, {}, {},
              [](const FrameGraph& graph, const TechniqueOptions& options) {
                return options.msaa > 1 && has_resource<kVisibilityIdsTarget>(graph, options);
              },
              identifiers<DebugViews::Identify::Shared>},
};

}  // namespace

std::span<const DebugView> debug_view_table() { return kViews; }

const DebugView* find_debug_view(std::string_view name) {
  for (const DebugView& view : kViews) {
    if (view.name == name) return &view;
  }
  return nullptr;
}

std::string debug_view_names() {
  std::string names;
  for (const DebugView& view : kViews) names += (names.empty() ? "" : ", ") + std::string(view.name);
  return names;
}

std::vector<OfferedView> offered_views(const FrameGraph& graph, const TechniqueOptions& options) {
  std::vector<OfferedView> views;
  for (const DebugView& row : kViews) {
    // Counting writes image atomics, which the compute-free tier lacks.
    if (options.compute_free && (row.needs.count_lights || row.needs.count_fragments)) continue;
    if (row.offered(graph, options)) views.push_back({std::string(row.name), std::string(row.help)});
  }
  for (const ViewableResource& resource : graph.viewable()) {
    const Visualiser* visualiser = visualiser_for(resource.kind);
    if (!visualiser || find_debug_view(resource.name)) continue;
    views.push_back({resource.name, std::string(visualiser->shows) +
                                        (resource.written_by.empty() ? "" : " (written by the " + resource.written_by + " pass)")});
  }
  return views;
}

std::string view_names(const std::vector<OfferedView>& views) {
  std::string names;
  for (const OfferedView& view : views) names += (names.empty() ? "" : ", ") + view.name;
  return names;
}

std::optional<SelectedView> select_view(std::string_view name, const FrameGraph& graph) {
  if (const DebugView* row = find_debug_view(name)) return SelectedView{row, resource_of(*row, graph)};
  const ResourceId id = graph.find(std::string(name));
  if (visualiser_for(graph.view_kind(id))) return SelectedView{nullptr, id};
  return std::nullopt;
}

DebugViews::DebugViews(GpuAssets& gpu, const TechniqueOptions& options)
    : gpu_(gpu),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa),
      cluster_grid_(options.cluster_grid),
      z_slicing_(options.z_slicing),
      samples_(options.msaa),
      depth_sampler_(gfx::create_sampler()) {
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void DebugViews::resize(const FrameTargets& targets) {
  size_ = targets.size;
  counts_ = gfx::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(counts_.id(), 1, GL_R32UI, targets.size.x, targets.size.y);
  const std::size_t blocks = static_cast<std::size_t>((targets.size.x + 15) / 16) * static_cast<std::size_t>((targets.size.y + 15) / 16);
  block_sums_ = gfx::create_buffer();
  glNamedBufferStorage(block_sums_.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(blocks, 1) * sizeof(GLuint)), nullptr, 0);
  sums_ = std::make_unique<gfx::ReadbackRing>(std::max<std::size_t>(blocks, 1) * sizeof(GLuint));
  thumbnail_size_ = {kThumbnailWidth, std::max(1, kThumbnailWidth * targets.size.y / std::max(targets.size.x, 1))};
  thumbnails_ = gfx::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(thumbnails_.id(), 1, GL_RGBA8, thumbnail_size_.x * kThumbnailColumns,
                     thumbnail_size_.y * (kThumbnailCount / kThumbnailColumns));
  thumbnail_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(thumbnail_framebuffer_.id(), GL_COLOR_ATTACHMENT0, thumbnails_.id(), 0);
}

void DebugViews::add_gbuffer_pass(FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) {
  add_geometry_pass(graph, gbuffer_, gpu_.shaders().get({"common/mesh.vert", "deferred/geometry.frag"}), frame, targets);
}

void DebugViews::add_counting_pass(FrameGraph& graph, const DebugViewNeeds& needs) {
  // The counters outlive the frame (their sums go back through sums_), so
  // they are the views' own, imported.
  const ResourceId counts = graph.import_texture(needs.count_fragments ? "fragment-counts" : "light-counts", counts_.id(),
                                                         {GL_R32UI, size_, 1}, ViewKind::Counts);
  graph.add_pass("clear counters", [&](PassBuilder& pass) { pass.write(counts, Access::Transfer); },
                 [this, fragments = needs.count_fragments](const PassResources&) {
                   const GLuint zero = 0;
                   glClearTexImage(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
                   glBindImageTexture(fragments ? 1 : 0, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
                 }, false);
}

void DebugViews::declare_reads(const SelectedView& view, PassBuilder& pass, const FrameGraph& graph,
                               const FrameContext& frame) {
  pass.read(frame.scene_depth, Access::Sampled);
  if (view.row && view.row->needs.gbuffer) {
    if (const std::optional<lighting::GBuffer::Found> found = lighting::GBuffer::find(graph)) {
      for (std::size_t i = 0; i < found->count; ++i) pass.read(found->resources[i], Access::Sampled);
    }
  }
  if (view.resource.valid()) pass.read(view.resource, Access::Sampled);
}

void DebugViews::declare_thumbnail_reads(PassBuilder& pass, const FrameGraph& graph, const FrameContext& frame) {
  for (const std::string_view name : kThumbnailViews) declare_reads(*select_view(name, graph), pass, graph, frame);
}

void DebugViews::draw_into_viewport(const SelectedView& view, const DebugViewFrame& frame, const PassResources& res,
                                    glm::vec2 origin, glm::vec2 scale) {
  if (view.row && view.row->draw) {
    view.row->draw(*this, frame, res, origin, scale);
    return;
  }
  const Visualiser* visualiser = visualiser_for(frame.graph.view_kind(view.resource));
  if (visualiser) visualiser->draw(*this, view.resource, frame, res, origin, scale);
  else show_nothing();  // the frame lacks what the view shows
}

void DebugViews::draw_thumbnails(const DebugViewFrame& frame, const PassResources& res) {
  glBindFramebuffer(GL_FRAMEBUFFER, thumbnail_framebuffer_.id());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  for (int index = 0; index < kThumbnailCount; ++index) {
    // Top row first on screen: GL's rows run bottom-up.
    const glm::ivec2 cell(index % kThumbnailColumns, kThumbnailCount / kThumbnailColumns - 1 - index / kThumbnailColumns);
    glViewport(cell.x * thumbnail_size_.x, cell.y * thumbnail_size_.y, thumbnail_size_.x, thumbnail_size_.y);
    draw_into_viewport(*select_view(kThumbnailViews[static_cast<std::size_t>(index)], frame.graph), frame, res,
                       glm::vec2(cell * thumbnail_size_), glm::vec2(frame.targets.size) / glm::vec2(thumbnail_size_));
  }
}

void DebugViews::draw(const SelectedView& view, const DebugViewFrame& frame, const PassResources& res, GLuint output_framebuffer) {
  // Every view is a full-screen pass into the output.
  glBindFramebuffer(GL_FRAMEBUFFER, output_framebuffer);
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  draw_into_viewport(view, frame, res, glm::vec2(0.0f), glm::vec2(1.0f));
}

void DebugViews::show_gbuffer(std::string_view target, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                              glm::vec2 scale) {
  const std::optional<lighting::GBuffer::Found> gbuffer = lighting::GBuffer::find(frame.graph);
  if (!gbuffer) {
    show_nothing();
    return;
  }
  lighting::GBuffer::bind_textures(res, *gbuffer);
  std::vector<gfx::ShaderDefine> defines = lighting::GBuffer::defines(gbuffer->layout);
  defines.push_back({"SHOW_" + std::string(target)});
  draw_show(defines, frame, origin, scale);
}

void DebugViews::draw_show(const std::vector<gfx::ShaderDefine>& defines, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
  gfx::ShaderProgram& show = gpu_.shaders().get({"post/fullscreen.vert", "debug/show.frag"}, defines);
  show.set("u_bounds_min", frame.bounds_min);
  show.set("u_bounds_max", frame.bounds_max);
  show.set("u_thumbnail_origin", origin);
  show.set("u_thumbnail_scale", scale);
  show.use();
  fullscreen_.draw();
}

void DebugViews::show_depth(ResourceId depth, const DebugViewFrame& frame, const PassResources& res, glm::vec2 origin,
                            glm::vec2 scale) {
  glBindTextureUnit(5, res.texture(depth));
  draw_show({{"SHOW_DEPTH"}}, frame, origin, scale);
}

void DebugViews::show_counts(ResourceId counts, const DebugViewFrame& frame, const PassResources& res) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  const bool fragments = frame.graph.find("fragment-counts") == counts;
  const float scale_max = fragments ? 64.0f : 2.0f * static_cast<float>(std::max<std::size_t>(frame.frame.lights.size(), 1));
  gfx::ShaderProgram& heatmap = gpu_.shaders().get({"post/fullscreen.vert", "debug/heatmap.frag"});
  heatmap.set("u_scale_max", scale_max);
  glBindImageTexture(0, res.texture(counts), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  heatmap.use();
  fullscreen_.draw();
}

void DebugViews::show_identifiers(ResourceId identifiers, const PassResources& res, Identify what) {
  // Draw and Material look the identifier up in the visibility buffer's units
  // and the frame's instances, which its passes left bound.
  static constexpr const char* kDefines[] = {"SHOW_VALUE", "SHOW_DRAW", "SHOW_MATERIAL", "SHOW_SHARED"};
  glBindTextureUnit(kVisibilityUnit, res.texture(identifiers));
  gpu_.shaders().get({"post/fullscreen.vert", "debug/identifiers.frag"}, {{kDefines[static_cast<int>(what)]}}).use();
  const bool over_image = what == Identify::Shared;
  if (over_image) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  fullscreen_.draw();
  if (over_image) glDisable(GL_BLEND);
}

void DebugViews::show_shadow_atlas(ResourceId atlas, const PassResources& res) {
  glBindTextureUnit(0, res.texture(atlas));
  glBindSampler(0, depth_sampler_.id());
  gpu_.shaders().get({"post/fullscreen.vert", "debug/shadow_atlas.frag"}).use();
  fullscreen_.draw();
  glBindSampler(0, 0);
}

void DebugViews::show_over_gbuffer(const char* fragment_shader, const DebugViewFrame& frame, const PassResources& res, bool blend) {
  const std::optional<lighting::GBuffer::Found> gbuffer = lighting::GBuffer::find(frame.graph);
  if (!gbuffer) return;  // nothing to draw over
  lighting::GBuffer::bind_textures(res, *gbuffer);
  if (blend) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  gpu_.shaders().get({"post/fullscreen.vert", fragment_shader}, lighting::GBuffer::defines(gbuffer->layout)).use();
  fullscreen_.draw();
  glDisable(GL_BLEND);
}

void DebugViews::show_nothing() {
  // Grey says the view has nothing here; the scissor keeps a thumbnail's clear in its cell.
  GLint viewport[4];
  glGetIntegerv(GL_VIEWPORT, viewport);
  glScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
  glEnable(GL_SCISSOR_TEST);
  const float grey[] = {0.15f, 0.15f, 0.15f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, grey);
  glDisable(GL_SCISSOR_TEST);
}

void DebugViews::show_light_sum(ResourceId sum, const PassResources& res, glm::vec2 origin, glm::vec2 scale) {
  // An image of the frame's own size and samples, or one of the post-process
  // chains' (a single sample, a fraction of the size), stretched over the view.
  const TextureDesc& desc = res.texture_desc(sum);
  const bool single = desc.samples == 1 && samples_ > 1;
  gfx::ShaderProgram& program =
      gpu_.shaders().get({"post/fullscreen.vert", "debug/light_sum.frag"}, single ? std::vector<gfx::ShaderDefine>{{"SINGLE_SAMPLE"}} : std::vector<gfx::ShaderDefine>{});
  program.set("u_thumbnail_origin", origin);
  program.set("u_thumbnail_scale", scale * glm::vec2(desc.size) / glm::vec2(glm::max(size_, glm::ivec2(1))));
  glBindTextureUnit(0, res.texture(sum));
  program.use();
  fullscreen_.draw();
}

void DebugViews::send_counts(const DebugViewNeeds& needs) {
  const glm::ivec2 blocks = (size_ + 15) / 16;
  if (blocks.x <= 0 || blocks.y <= 0) return;
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, counts_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBlockSumsBinding, block_sums_.id());
  gpu_.shaders().get({"debug/sum_counts.comp"}).use();
  glDispatchCompute(static_cast<GLuint>(blocks.x), static_cast<GLuint>(blocks.y), 1);
  const std::size_t bytes = static_cast<std::size_t>(blocks.x) * static_cast<std::size_t>(blocks.y) * sizeof(GLuint);
  // The tag: the pixels averaged over, and whether they counted fragments.
  const std::uint64_t pixels = static_cast<std::uint64_t>(size_.x) * static_cast<std::uint64_t>(size_.y);
  (void)sums_->copy(block_sums_.id(), 0, bytes, pixels << 1 | (needs.count_fragments ? 1u : 0u));
}

std::vector<DebugViews::CountAverage> DebugViews::take_averages() {
  std::vector<CountAverage> averages;
  if (!sums_) return averages;
  sums_->poll([&](const void* data, std::size_t bytes, std::uint64_t tag) {
    std::vector<GLuint> sums(bytes / sizeof(GLuint));
    std::memcpy(sums.data(), data, sums.size() * sizeof(GLuint));
    const double pixels = static_cast<double>(std::max<std::uint64_t>(tag >> 1, 1));
    averages.push_back({static_cast<double>(std::accumulate(sums.begin(), sums.end(), std::uint64_t{0})) / pixels, (tag & 1u) != 0});
  });
  return averages;
}

void DebugViews::show_depth_slices(const DebugViewFrame& frame, const PassResources& res) {
  const glm::uvec3 dims = cluster_grid_.at(frame.targets.size);
  if (!slicing_ || slicing_->dims() != dims) slicing_ = std::make_unique<lighting::ClusterGrid>(dims, z_slicing_);
  slicing_->update(frame.frame.projection, frame.frame.near_plane, frame.frame.far_plane);
  slicing_->bind();
  gfx::ShaderProgram& program = gpu_.shaders().get({"post/fullscreen.vert", "debug/light_bins.frag"}, {{"DEPTH_SLICES"}});
  glBindTextureUnit(5, res.texture(frame.frame.scene_depth));
  program.use();
  fullscreen_.draw();
}

void DebugViews::show_light_bins(ResourceId lists, const DebugViewFrame& frame, const PassResources& res) {
  const lighting::LightBins* bins = frame.graph.published<lighting::LightBins>();
  if (!bins || bins->lists != lists) {
    show_nothing();  // lists whose technique did not say how pixels map to them
    return;
  }
  bins->list->bind();
  if (bins->binning == lighting::LightBins::Binning::Clusters) glBindBufferBase(GL_UNIFORM_BUFFER, kClusterUniformBinding, bins->grid_uniforms);
  gfx::ShaderProgram& program = gpu_.shaders().get({"post/fullscreen.vert", "debug/light_bins.frag"},
                                                   {{"LIGHT_BINS", bins->binning == lighting::LightBins::Binning::Tiles ? "1" : "2"}});
  program.set("u_tiles", bins->tiles);
  program.set("u_tile_size", bins->tile_size);
  // A bin can hold every light: the map tops out there.
  program.set("u_scale_max", static_cast<float>(std::max<std::size_t>(frame.frame.lights.size(), 1)));
  glBindTextureUnit(5, res.texture(frame.frame.scene_depth));
  program.use();
  fullscreen_.draw();
}

}  // namespace atrium::render
