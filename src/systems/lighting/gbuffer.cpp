#include "systems/lighting/gbuffer.hpp"

#include "gfx/depth.hpp"
#include "render/frame_graph.hpp"

#include "gfx/depth.hpp"

namespace atrium::lighting {

std::span<const GBuffer::Target> GBuffer::targets(GBufferLayout layout) {
  switch (layout) {
    case GBufferLayout::Compact: return kCompactLayout;
    case GBufferLayout::Thin: return kThinLayout;
    case GBufferLayout::Full: break;
  }
  return kFullLayout;
}

GBuffer::GBuffer(gfx::ShaderLibrary& shaders, GBufferLayout layout, int samples) : layout_(layout), samples_(samples) {
  if (samples_ > 1) edges_ = &shaders.get({"post/fullscreen.vert", "deferred/edges.frag"}, defines());
}

std::vector<gfx::ShaderDefine> GBuffer::defines() const {
  if (layout_ == GBufferLayout::Thin) return {{"THIN_GBUFFER"}};
  return {};
}

void GBuffer::resize(glm::ivec2 size, GLuint depth_stencil) {
  size_ = size;
  framebuffer_ = gfx::create_framebuffer();
  const auto layout = targets();
  std::array<GLenum, kMaxTargets> attachments{};
  for (std::size_t i = 0; i < layout.size(); ++i) {
    textures_[i] = gfx::create_render_target(layout[i].format, size.x, size.y, samples_);
    attachments[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glNamedFramebufferTexture(framebuffer_.id(), attachments[i], textures_[i].id(), 0);
  }
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth_stencil, 0);
  glNamedFramebufferDrawBuffers(framebuffer_.id(), static_cast<GLsizei>(layout.size()), attachments.data());
  gfx::require_complete(framebuffer_.id(), "G-buffer");
}

void GBuffer::draw_geometry(gfx::ShaderProgram& program, const FrameContext& frame) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, size_.x, size_.y);
  // Zero everywhere marks "no geometry" in both layouts (position.w, distance).
  const auto layout = targets();
  for (GLint i = 0; i < static_cast<GLint>(layout.size()); ++i) {
    if (layout[static_cast<std::size_t>(i)].format == GL_RGBA32UI) {
      const GLuint zero[] = {0, 0, 0, 0};
      glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, i, zero);
    } else {
      const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
      glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
    }
  }
  glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, gfx::kDepthFar, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  // The albedo target is sRGB: GL encodes the linear values written to it.
  glEnable(GL_FRAMEBUFFER_SRGB);
  program.use();
  frame.draw_first_pass(draw_items);
  glDisable(GL_FRAMEBUFFER_SRGB);
  if (edges_) mark_edges();
}

void GBuffer::mark_edges() const {
  // A full-screen triangle covers every sample, so a pixel the shader keeps gets
  // the bit in all of its samples.
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilMask(kEdgeStencilBit);
  glStencilFunc(GL_ALWAYS, kEdgeStencilBit, kEdgeStencilBit);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  bind_textures();
  edges_->use();
  fullscreen_.draw();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
}

void GBuffer::bind_textures() const {
  std::array<GLuint, kMaxTargets> names{};
  const std::size_t count = targets().size();
  for (std::size_t i = 0; i < count; ++i) names[i] = textures_[i].id();
  glBindTextures(0, static_cast<GLsizei>(count), names.data());
}

void GBuffer::draw_fullscreen(const SampleRatePrograms& programs, const FrameTargets& targets) const {
  glBindFramebuffer(GL_FRAMEBUFFER, targets.lighting_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  bind_textures();
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
