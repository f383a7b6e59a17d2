#include "systems/lighting/debug_views.hpp"

#include <cstring>
#include <numeric>
#include <vector>


namespace atrium::lighting {

namespace {
constexpr GLuint kBlockSumsBinding = 11;  // shaders/debug/sum_counts.comp
}  // namespace

namespace {

bool always(const LightingTechnique&, const TechniqueOptions&, int) { return true; }
bool has_gbuffer(const LightingTechnique& technique, const TechniqueOptions&, int) { return technique.gbuffer() != nullptr; }

template <const char* kTarget>
void gbuffer_target(DebugViews& views, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
  views.show_gbuffer(kTarget, frame, origin, scale);
}
constexpr char kPosition[] = "POSITION", kNormal[] = "NORMAL", kAlbedo[] = "ALBEDO", kMetallicRoughness[] = "METALLIC_ROUGHNESS",
               kEmissive[] = "EMISSIVE", kDepth[] = "DEPTH";

constexpr DebugViewNeeds kGBuffer{.gbuffer = true};

const std::array kViews{
    DebugView{"position", "world position, scaled to the scene's bounds", kGBuffer, always, gbuffer_target<kPosition>},
    DebugView{"normal", "shading normal (normal maps applied)", kGBuffer, always, gbuffer_target<kNormal>},
    DebugView{"albedo", "base colour (grey in the light pre-pass's thin G-buffer, which has none)", kGBuffer, always, gbuffer_target<kAlbedo>},
    DebugView{"metallic-roughness", "metallic in red, roughness in green", kGBuffer, always, gbuffer_target<kMetallicRoughness>},
    DebugView{"emissive", "emitted light, tone-mapped", kGBuffer, always, gbuffer_target<kEmissive>},
    DebugView{"depth", "view depth on a log scale, near white", kGBuffer, always, gbuffer_target<kDepth>},
    DebugView{"light-volumes", "outlines of the light spheres over the lit image", kGBuffer, always,
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) {
                views.show_over_gbuffer("debug/outlines.frag", frame, false);
              }},
    DebugView{"heatmap", "lights evaluated per pixel by the mode", {.count_lights = true}, always,
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) {
                // The top of the map at twice the light count: forward's overdraw
                // can exceed one pass over all lights.
                views.show_counts(2.0f * static_cast<float>(std::max<std::size_t>(frame.frame.lights.size(), 1)));
              }},
    DebugView{"light-lists", "lights in each pixel's tile or cluster list (magenta: a bin that did not fit this frame)", {},
              [](const LightingTechnique& technique, const TechniqueOptions&, int) {
                return technique.bind_light_bins().binning != LightingTechnique::Binning::None;
              },
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) { views.show_light_bins(false, frame); }},
    DebugView{"depth-slices", "the cluster depth slices (--cluster-grid, --z-slicing)", {}, always,
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) { views.show_light_bins(true, frame); }},
    DebugView{"fragments", "fragments the geometry passes rasterise per pixel (overdraw)", {.count_fragments = true}, always,
              [](DebugViews& views, const DebugViewFrame&, glm::vec2, glm::vec2) { views.show_counts(64.0f); }},
    DebugView{"diffuse-light", "the diffuse light sum, apart (deferred modes)", {.split_lighting = true}, has_gbuffer,
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
                // Only a deferred mode's lighting passes write the sums apart.
                views.show_light_sum(frame.technique.gbuffer() ? frame.targets.diffuse_light : 0, origin, scale);
              }},
    DebugView{"specular-light", "the specular light sum, apart (deferred modes)", {.split_lighting = true}, has_gbuffer,
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
                views.show_light_sum(frame.technique.gbuffer() ? frame.targets.specular_light : 0, origin, scale);
              }},
    DebugView{"light-buffer", "light summed before materials (light-prepass)", {},
              [](const LightingTechnique& technique, const TechniqueOptions&, int) { return technique.light_buffer() != 0; },
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
                views.show_light_sum(frame.technique.light_buffer(), origin, scale);
              }},
    DebugView{"msaa-edges", "the pixels the deferred modes shade per sample, in red (with --msaa)", kGBuffer,
              [](const LightingTechnique& technique, const TechniqueOptions& options, int) {
                return options.msaa > 1 && technique.gbuffer() != nullptr;
              },
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) {
                views.show_over_gbuffer("debug/msaa_edges.frag", frame, true);
              }},
    DebugView{"shadow-atlas", "the shadow maps' depths (with --shadows)", {},
              [](const LightingTechnique&, const TechniqueOptions&, int shadows) { return shadows > 0; },
              [](DebugViews& views, const DebugViewFrame& frame, glm::vec2, glm::vec2) { views.show_shadow_atlas(frame.shadow_atlas); }},
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

DebugViews::DebugViews(assets::GpuAssets& gpu, const TechniqueOptions& options)
    : gpu_(gpu),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa),
      cluster_dims_(options.cluster_grid),
      z_slicing_(options.z_slicing),
      depth_sampler_(gfx::create_sampler()) {
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(depth_sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

void DebugViews::resize(const FrameTargets& targets) {
  size_ = targets.size;
  gbuffer_.resize(targets.size, targets.depth_stencil);
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

void DebugViews::draw_thumbnails(const DebugViewFrame& frame) {
  glBindFramebuffer(GL_FRAMEBUFFER, thumbnail_framebuffer_.id());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  for (int index = 0; index < kThumbnailCount; ++index) {
    // Top row first on screen: GL's rows run bottom-up.
    const glm::ivec2 cell(index % kThumbnailColumns, kThumbnailCount / kThumbnailColumns - 1 - index / kThumbnailColumns);
    glViewport(cell.x * thumbnail_size_.x, cell.y * thumbnail_size_.y, thumbnail_size_.x, thumbnail_size_.y);
    const DebugView* view = find_debug_view(kThumbnailViews[static_cast<std::size_t>(index)]);
    view->draw(*this, frame, glm::vec2(cell * thumbnail_size_), glm::vec2(frame.targets.size) / glm::vec2(thumbnail_size_));
  }
}

void DebugViews::show_gbuffer(std::string_view target, const DebugViewFrame& frame, glm::vec2 origin, glm::vec2 scale) {
  const GBuffer& gbuffer = gbuffer_of(frame);
  gbuffer.bind_textures();
  glBindTextureUnit(5, frame.targets.depth_stencil);
  std::vector<gfx::ShaderDefine> defines = gbuffer.defines();
  defines.push_back({"SHOW_" + std::string(target)});
  gfx::ShaderProgram& show = gpu_.shaders().get({"post/fullscreen.vert", "debug/show.frag"}, defines);
  show.set("u_bounds_min", frame.bounds_min);
  show.set("u_bounds_max", frame.bounds_max);
  show.set("u_thumbnail_origin", origin);
  show.set("u_thumbnail_scale", scale);
  show.use();
  fullscreen_.draw();
}

void DebugViews::begin_counting(const DebugViewNeeds& needs) {
  const GLuint zero = 0;
  glClearTexImage(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindImageTexture(needs.count_fragments ? 1 : 0, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void DebugViews::draw(const DebugView& view, const DebugViewFrame& frame, GLuint output_framebuffer) {
  // Every view is a full-screen pass into the output. A view of the G-buffer
  // in a mode without one first fills the views' own (and the depth buffer).
  if (view.needs.gbuffer && !frame.technique.gbuffer()) {
    gbuffer_.draw_geometry(gpu_.shaders().get({"common/mesh.vert", "deferred/geometry.frag"}), frame.frame);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, output_framebuffer);
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  view.draw(*this, frame, glm::vec2(0.0f), glm::vec2(1.0f));
}

void DebugViews::show_counts(float scale_max) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  gfx::ShaderProgram& heatmap = gpu_.shaders().get({"post/fullscreen.vert", "debug/heatmap.frag"});
  heatmap.set("u_scale_max", scale_max);
  glBindImageTexture(0, counts_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  heatmap.use();
  fullscreen_.draw();
}

void DebugViews::show_shadow_atlas(GLuint atlas) {
  if (atlas == 0) {
    show_light_sum(0, glm::vec2(0.0f), glm::vec2(1.0f));  // grey: no atlas this frame
    return;
  }
  glBindTextureUnit(0, atlas);
  glBindSampler(0, depth_sampler_.id());
  gpu_.shaders().get({"post/fullscreen.vert", "debug/shadow_atlas.frag"}).use();
  fullscreen_.draw();
  glBindSampler(0, 0);
}

void DebugViews::show_over_gbuffer(const char* fragment_shader, const DebugViewFrame& frame, bool blend) {
  const GBuffer& gbuffer = gbuffer_of(frame);
  gbuffer.bind_textures();
  if (blend) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }
  gpu_.shaders().get({"post/fullscreen.vert", fragment_shader}, gbuffer.defines()).use();
  fullscreen_.draw();
  glDisable(GL_BLEND);
}

void DebugViews::show_light_sum(GLuint sum, glm::vec2 origin, glm::vec2 scale) {
  if (sum == 0) {
    // Grey says the sums are not there; the scissor keeps a thumbnail's clear in its cell.
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    glScissor(viewport[0], viewport[1], viewport[2], viewport[3]);
    glEnable(GL_SCISSOR_TEST);
    const float grey[] = {0.15f, 0.15f, 0.15f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, grey);
    glDisable(GL_SCISSOR_TEST);
    return;
  }
  gfx::ShaderProgram& program = gpu_.shaders().get({"post/fullscreen.vert", "debug/light_sum.frag"});
  program.set("u_thumbnail_origin", origin);
  program.set("u_thumbnail_scale", scale);
  glBindTextureUnit(0, sum);
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

void DebugViews::show_light_bins(bool depth_slices, const DebugViewFrame& frame) {
  std::vector<gfx::ShaderDefine> defines;
  LightingTechnique::LightBins bins;
  if (depth_slices) {
    if (!slicing_) slicing_ = std::make_unique<ClusterGrid>(cluster_dims_, z_slicing_);
    slicing_->update(frame.frame.projection, frame.frame.near_plane, frame.frame.far_plane);
    slicing_->bind();
    defines.push_back({"DEPTH_SLICES"});
  } else {
    bins = frame.technique.bind_light_bins();
    if (bins.binning == LightingTechnique::Binning::None) {
      // This mode keeps no lists: a flat grey says so rather than a stale picture.
      const float grey[] = {0.15f, 0.15f, 0.15f, 1.0f};
      glClearBufferfv(GL_COLOR, 0, grey);
      return;
    }
    defines.push_back({"LIGHT_BINS", bins.binning == LightingTechnique::Binning::Tiles ? "1" : "2"});
  }
  gfx::ShaderProgram& program = gpu_.shaders().get({"post/fullscreen.vert", "debug/light_bins.frag"}, defines);
  if (!depth_slices) {
    program.set("u_tiles", bins.tiles);
    program.set("u_tile_size", bins.tile_size);
    program.set("u_list_capacity", bins.capacity);
    // A bin can hold every light: the map tops out there.
    program.set("u_scale_max", static_cast<float>(std::max<std::size_t>(frame.frame.lights.size(), 1)));
  }
  glBindTextureUnit(5, frame.targets.depth_stencil);
  program.use();
  fullscreen_.draw();
}

}  // namespace atrium::lighting
