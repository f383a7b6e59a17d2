#include "gfx/debug_output.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

#include "gfx/gl.hpp"

namespace atrium::gfx {
namespace {
std::atomic<std::uint64_t> g_errors{0};
std::mutex g_last_mutex;
std::string g_last_error;

void GLAPIENTRY on_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* /*user*/) {
  // Shader compile errors reach the user through ShaderError, with file:line.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  const std::string text(message, length >= 0 ? static_cast<std::size_t>(length) : std::char_traits<char>::length(message));
  if (type == GL_DEBUG_TYPE_ERROR) {
    ++g_errors;
    {
      std::lock_guard lock(g_last_mutex);
      g_last_error = text;
    }
    std::fprintf(stderr, "GL error %u: %s\n", id, text.c_str());
  } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
    std::fprintf(stderr, "GL warning %u: %s\n", id, text.c_str());
  }
}
}  // namespace

void enable_debug_output() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(on_debug_message, nullptr);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::uint64_t gl_error_count() { return g_errors.load(); }

std::string last_gl_error() {
  std::lock_guard lock(g_last_mutex);
  return g_last_error;
}

void reset_gl_error_count() { g_errors = 0; }

}  // namespace atrium::gfx
