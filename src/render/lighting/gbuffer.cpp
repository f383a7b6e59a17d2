#include "render/lighting/gbuffer.hpp"

#include <string>

#include "gfx/depth.hpp"
#include "gfx/gl_features.hpp"
#include "render/frame_graph.hpp"

namespace atrium::lighting {

std::span<const GBuffer::Target> GBuffer::targets(GBufferLayout layout) {
  switch (layout) {
    case GBufferLayout::Compact: return kCompactLayout;
    case GBufferLayout::Thin: return kThinLayout;
    case GBufferLayout::Full: break;
  }
  return kFullLayout;
}

GBuffer::GBuffer(gfx::ShaderLibrary& shaders, GBufferLayout layout, int samples, EdgeMarks marks)
    : layout_(layout), samples_(samples) {
  if (samples_ > 1 && marks == EdgeMarks::Stencil) edges_ = &shaders.get({"post/fullscreen.vert", "deferred/edges.frag"}, defines());
}

std::vector<gfx::ShaderDefine> GBuffer::defines(GBufferLayout layout) {
  if (layout == GBufferLayout::Thin) return {{"THIN_GBUFFER"}};
  return {};
}

std::vector<gfx::ShaderDefine> GBuffer::defines() const { return defines(layout_); }

void GBuffer::create_targets(render::PassBuilder& pass, glm::ivec2 size, render::ResourceId depth) {
  size_ = size;
  depth_ = depth;
  const auto layout = targets();
  for (std::size_t i = 0; i < layout.size(); ++i) {
    resources_[i] =
        pass.create(std::string("gbuffer.") + layout[i].name, render::TextureDesc{layout[i].format, size, samples_}, render::ViewKind::GBuffer);
  }
  pass.write(depth, render::Access::Attachment);
}

void GBuffer::read_targets(render::PassBuilder& pass) const {
  for (const render::ResourceId target : resources()) pass.read(target, render::Access::Sampled);
}

std::optional<GBuffer::Found> GBuffer::find(const render::FrameGraph& graph) {
  for (const GBufferLayout layout : {GBufferLayout::Full, GBufferLayout::Compact, GBufferLayout::Thin}) {
    Found found{layout, {}, 0};
    for (const Target& target : targets(layout)) {
      const render::ResourceId id = graph.find(std::string("gbuffer.") + target.name);
      if (!id.valid()) break;
      found.resources[found.count++] = id;
    }
    if (found.count == targets(layout).size()) return found;
  }
  return std::nullopt;
}

void GBuffer::draw_geometry(const render::PassResources& res, gfx::ShaderProgram& program, const render::FrameContext& frame) {
  const auto layout = targets();
  const GLuint framebuffer = res.framebuffer(resources(), depth_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size_.x, size_.y);
  // Zero everywhere marks "no geometry" in both layouts (position.w, distance).
  for (GLint i = 0; i < static_cast<GLint>(layout.size()); ++i) {
    if (layout[static_cast<std::size_t>(i)].format == GL_RGBA32UI) {
      const GLuint zero[] = {0, 0, 0, 0};
      glClearNamedFramebufferuiv(framebuffer, GL_COLOR, i, zero);
    } else {
      const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
      glClearNamedFramebufferfv(framebuffer, GL_COLOR, i, zero);
    }
  }
  glClearNamedFramebufferfi(framebuffer, GL_DEPTH_STENCIL, 0, gfx::kDepthFar, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  // The albedo target is sRGB: GL encodes the linear values written to it
  // (ES always does).
  const bool srgb_switch = gfx::gl_features().srgb_write_control;
  if (srgb_switch) glEnable(GL_FRAMEBUFFER_SRGB);
  program.use();
  frame.draw_first_pass(res, render::draw_items);
  if (srgb_switch) glDisable(GL_FRAMEBUFFER_SRGB);
  if (edges_) mark_edges(res);
}

void GBuffer::mark_edges(const render::PassResources& res) const {
  // A full-screen triangle covers every sample, so a pixel the shader keeps gets
  // the bit in all of its samples.
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(kEdgeStencilBit);
  glStencilFunc(GL_ALWAYS, kEdgeStencilBit, kEdgeStencilBit);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  bind_textures(res);
  edges_->use();
  fullscreen_.draw();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
}

void GBuffer::bind_textures(const render::PassResources& res, const Found& found) {
  std::array<GLuint, kMaxTargets> names{};
  for (std::size_t i = 0; i < found.count; ++i) names[i] = res.texture(found.resources[i]);
  glBindTextures(0, static_cast<GLsizei>(found.count), names.data());
}

void GBuffer::bind_textures(const render::PassResources& res) const { bind_textures(res, {layout_, resources_, targets().size()}); }

void GBuffer::draw_fullscreen(const render::PassResources& res, const SampleRatePrograms& programs, const render::FrameContext& frame,
                              const render::FrameTargets& targets) const {
  glBindFramebuffer(GL_FRAMEBUFFER, render::lighting_framebuffer(res, frame));
  glViewport(0, 0, targets.size.x, targets.size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  bind_textures(res);
  programs.draw([&](gfx::ShaderProgram& program) {
    program.use();
    fullscreen_.draw();
  });
}

std::size_t GBuffer::bytes_per_pixel(GBufferLayout layout) {
  std::size_t bytes = render::texture_bytes({gfx::kDepthStencilFormat, {1, 1}, 1});
  for (const Target& target : targets(layout)) bytes += render::texture_bytes({target.format, {1, 1}, 1});
  return bytes;
}

}  // namespace atrium::lighting
