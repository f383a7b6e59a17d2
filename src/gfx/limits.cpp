#include "gfx/limits.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

#include "gfx/gl.hpp"
#include "gfx/gl_features.hpp"

namespace atrium::gfx {

std::uint64_t storage_block_limit() {
  if (!gl_features().storage_buffers) return 0;
  GLint64 bytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
  return static_cast<std::uint64_t>(std::max<GLint64>(bytes, 0));
}

int max_texture_size() {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

bool texture_fits(unsigned format, int levels, glm::ivec2 size) {
  const GlFeatures& gl = gl_features();
  if (std::max(size.x, size.y) > max_texture_size()) return false;  // past it the proxy call itself is an error
  if (gl.es || !gl.texture_storage || !gl.level_queries) return true;
  glTexStorage2D(GL_PROXY_TEXTURE_2D, levels, format, size.x, size.y);
  GLint width = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
  return width != 0;
}

glm::ivec2 max_render_size() {
  GLint viewport[2] = {0, 0}, width = 0, height = 0, renderbuffer = 0;
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  const int texture = max_texture_size();
  if (gl_features().framebuffer_limits) {
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &width);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &height);
  } else {
    width = height = texture;
  }
  return {std::min({viewport[0], width, renderbuffer, texture}), std::min({viewport[1], height, renderbuffer, texture})};
}

int max_msaa_samples() {
  // The tiers draw into textures: without multisampled ones, no MSAA.
  if (!gl_features().multisample_textures) return 1;
  GLint samples = 0, color = 0, depth = 0, integer = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &samples);
  glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &color);
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &depth);
  glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &integer);
  return std::max(1, std::min({samples, color, depth, integer}));
}

bool is_software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string_view name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string_view::npos || name.find("softpipe") != std::string_view::npos ||
         name.find("lavapipe") != std::string_view::npos || name.find("SwiftShader") != std::string_view::npos;
}

std::uint32_t shader_loop_limit() { return is_software_renderer() ? 65535u : 0u; }

}  // namespace atrium::gfx
