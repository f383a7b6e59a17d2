#include "systems/lighting/debug_views.hpp"

#include <numeric>
#include <vector>

#include "gfx/gpu_waits.hpp"

namespace atrium::lighting {

int debug_view_index(std::string_view name) {
  for (std::size_t i = 0; i < kDebugViews.size(); ++i) {
    if (kDebugViews[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string debug_view_names() {
  std::string names;
  for (const auto name : kDebugViews) names += (names.empty() ? "" : ", ") + std::string(name);
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
  thumbnail_size_ = {kThumbnailWidth, std::max(1, kThumbnailWidth * targets.size.y / std::max(targets.size.x, 1))};
  thumbnails_ = gfx::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(thumbnails_.id(), 1, GL_RGBA8, thumbnail_size_.x * kThumbnailColumns,
                     thumbnail_size_.y * (kThumbnailCount / kThumbnailColumns));
  thumbnail_framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(thumbnail_framebuffer_.id(), GL_COLOR_ATTACHMENT0, thumbnails_.id(), 0);
}

void DebugViews::draw_thumbnails(const GBuffer& gbuffer, const FrameTargets& targets, glm::vec3 bounds_min,
                                 glm::vec3 bounds_max) {
  glBindFramebuffer(GL_FRAMEBUFFER, thumbnail_framebuffer_.id());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  for (int index = 0; index < kThumbnailCount; ++index) {
    // Top row first on screen: GL's rows run bottom-up.
    const glm::ivec2 cell(index % kThumbnailColumns, kThumbnailCount / kThumbnailColumns - 1 - index / kThumbnailColumns);
    glViewport(cell.x * thumbnail_size_.x, cell.y * thumbnail_size_.y, thumbnail_size_.x, thumbnail_size_.y);
    const int view = kThumbnailViews[static_cast<std::size_t>(index)];
    if (view == kDiffuseLightView || view == kSpecularLightView) {
      draw_light_sum(view == kDiffuseLightView ? targets.diffuse_light : targets.specular_light, glm::vec2(cell * thumbnail_size_),
                     glm::vec2(targets.size) / glm::vec2(thumbnail_size_));
      continue;
    }
    show_gbuffer(view, gbuffer, targets, bounds_min, bounds_max, glm::vec2(cell * thumbnail_size_),
                 glm::vec2(targets.size) / glm::vec2(thumbnail_size_));
  }
}

void DebugViews::show_gbuffer(int view, const GBuffer& gbuffer, const FrameTargets& targets, glm::vec3 bounds_min,
                              glm::vec3 bounds_max, glm::vec2 origin, glm::vec2 scale) {
  gbuffer.bind_textures();
  glBindTextureUnit(5, targets.depth_stencil);
  std::vector<gfx::ShaderDefine> defines = gbuffer.defines();
  defines.push_back({"DEBUG_VIEW", std::to_string(view)});
  gfx::ShaderProgram& show = gpu_.shaders().get({"post/fullscreen.vert", "debug/show.frag"}, defines);
  show.set("u_bounds_min", bounds_min);
  show.set("u_bounds_max", bounds_max);
  show.set("u_thumbnail_origin", origin);
  show.set("u_thumbnail_scale", scale);
  show.use();
  fullscreen_.draw();
}

void DebugViews::begin_counting(int view) {
  const GLuint zero = 0;
  glClearTexImage(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindImageTexture(view == kFragmentView ? 1 : 0, counts_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void DebugViews::draw(int view, const LightingTechnique& technique, const FrameContext& frame, const FrameTargets& targets,
                      GLuint output_framebuffer, glm::vec3 bounds_min, glm::vec3 bounds_max, GLuint shadow_atlas) {
  // Every view is a full-screen pass into the output. The G-buffer, depth and
  // outline views show the G-buffer the mode filled this frame, in its layout;
  // in a mode without one they first fill their own (and the depth buffer).
  const bool reads_gbuffer = view < kHeatmapView || view == kOutlineView || view == kMsaaEdgeView;
  const GBuffer* gbuffer = technique.gbuffer();
  if (reads_gbuffer && !gbuffer) {
    gbuffer_.draw_geometry(gpu_.shaders().get({"common/mesh.vert", "deferred/geometry.frag"}), frame);
    gbuffer = &gbuffer_;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, output_framebuffer);
  glViewport(0, 0, size_.x, size_.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  if (view == kHeatmapView || view == kFragmentView) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gfx::ShaderProgram& heatmap = gpu_.shaders().get({"post/fullscreen.vert", "debug/heatmap.frag"});
    // Lights: the top of the map at twice the light count (forward's overdraw can
    // exceed one pass over all lights). Fragments: at 64 per pixel.
    heatmap.set("u_scale_max", view == kFragmentView ? 64.0f : 2.0f * static_cast<float>(std::max<std::size_t>(frame.lights.size(), 1)));
    glBindImageTexture(0, counts_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    heatmap.use();
    fullscreen_.draw();
    return;
  }
  if (view == kLightListView || view == kDepthSliceView) {
    draw_light_bins(view, technique, frame, targets);
    return;
  }
  if (view == kDiffuseLightView || view == kSpecularLightView) {
    // Only a deferred mode's lighting passes write the sums apart.
    const GLuint sum = !technique.gbuffer() ? 0 : view == kDiffuseLightView ? targets.diffuse_light : targets.specular_light;
    draw_light_sum(sum, glm::vec2(0.0f), glm::vec2(1.0f));
    return;
  }
  if (view == kShadowAtlasView) {
    if (shadow_atlas == 0) {
      draw_light_sum(0, glm::vec2(0.0f), glm::vec2(1.0f));  // grey: no atlas this frame
      return;
    }
    glBindTextureUnit(0, shadow_atlas);
    glBindSampler(0, depth_sampler_.id());
    gpu_.shaders().get({"post/fullscreen.vert", "debug/shadow_atlas.frag"}).use();
    fullscreen_.draw();
    glBindSampler(0, 0);
    return;
  }
  if (view == kLightBufferView) {
    draw_light_sum(technique.light_buffer(), glm::vec2(0.0f), glm::vec2(1.0f));
    return;
  }
  if (view == kOutlineView) {
    gbuffer->bind_textures();
    gpu_.shaders().get({"post/fullscreen.vert", "debug/outlines.frag"}, gbuffer->defines()).use();
    fullscreen_.draw();
    return;
  }
  if (view == kMsaaEdgeView) {
    gbuffer->bind_textures();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gpu_.shaders().get({"post/fullscreen.vert", "debug/msaa_edges.frag"}, gbuffer->defines()).use();
    fullscreen_.draw();
    glDisable(GL_BLEND);
    return;
  }
  show_gbuffer(view, *gbuffer, targets, bounds_min, bounds_max, glm::vec2(0.0f), glm::vec2(1.0f));
}

void DebugViews::draw_light_sum(GLuint sum, glm::vec2 origin, glm::vec2 scale) {
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

double DebugViews::average_count() const {
  std::vector<GLuint> counts(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
  if (counts.empty()) return 0.0;
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  gfx::read_texture(counts_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, static_cast<GLsizei>(counts.size() * sizeof(GLuint)),
                    counts.data());
  return static_cast<double>(std::accumulate(counts.begin(), counts.end(), std::uint64_t{0})) / static_cast<double>(counts.size());
}

void DebugViews::draw_light_bins(int view, const LightingTechnique& technique, const FrameContext& frame,
                                 const FrameTargets& targets) {
  std::vector<gfx::ShaderDefine> defines;
  LightingTechnique::LightBins bins;
  if (view == kDepthSliceView) {
    if (!slicing_) slicing_ = std::make_unique<ClusterGrid>(cluster_dims_, z_slicing_);
    slicing_->update(frame.projection, frame.near_plane, frame.far_plane);
    slicing_->bind();
    defines.push_back({"DEPTH_SLICES"});
  } else {
    bins = technique.bind_light_bins();
    if (bins.binning == LightingTechnique::Binning::None) {
      // This mode keeps no lists: a flat grey says so rather than a stale picture.
      const float grey[] = {0.15f, 0.15f, 0.15f, 1.0f};
      glClearBufferfv(GL_COLOR, 0, grey);
      return;
    }
    defines.push_back({"LIGHT_BINS", bins.binning == LightingTechnique::Binning::Tiles ? "1" : "2"});
  }
  gfx::ShaderProgram& program = gpu_.shaders().get({"post/fullscreen.vert", "debug/light_bins.frag"}, defines);
  if (view == kLightListView) {
    program.set("u_tiles", bins.tiles);
    program.set("u_tile_size", bins.tile_size);
    program.set("u_list_capacity", bins.capacity);
    // A bin can hold every light: the map tops out there.
    program.set("u_scale_max", static_cast<float>(std::max<std::size_t>(frame.lights.size(), 1)));
  }
  glBindTextureUnit(5, targets.depth_stencil);
  program.use();
  fullscreen_.draw();
}

}  // namespace atrium::lighting
