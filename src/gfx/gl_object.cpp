#include "gfx/gl_object.hpp"

#include <atomic>

namespace atrium::gfx {
namespace {
std::array<std::atomic<std::int64_t>, kGlKindCount> g_live{};

std::atomic<std::int64_t>& live(GlKind kind) { return g_live[static_cast<std::size_t>(kind)]; }
}  // namespace

std::string_view gl_kind_name(GlKind kind) {
  static constexpr std::array<std::string_view, kGlKindCount> kNames{
      "buffer", "texture", "framebuffer", "vertex array", "shader", "program", "query", "sampler", "renderbuffer"};
  return kNames[static_cast<std::size_t>(kind)];
}

std::int64_t live_gl_objects(GlKind kind) { return live(kind).load(); }

std::int64_t live_gl_objects() {
  std::int64_t total = 0;
  for (const auto& counter : g_live) total += counter.load();
  return total;
}

bool gl_object_exists(GlKind kind, GLuint name) {
  switch (kind) {
    case GlKind::Buffer: return glIsBuffer(name);
    case GlKind::Texture: return glIsTexture(name);
    case GlKind::Framebuffer: return glIsFramebuffer(name);
    case GlKind::VertexArray: return glIsVertexArray(name);
    case GlKind::Shader: return glIsShader(name);
    case GlKind::Program: return glIsProgram(name);
    case GlKind::Query: return glIsQuery(name);
    case GlKind::Sampler: return glIsSampler(name);
    case GlKind::Renderbuffer: return glIsRenderbuffer(name);
  }
  return false;
}

namespace detail {
void count_created(GlKind kind) { ++live(kind); }

void destroy_gl_object(GlKind kind, GLuint name) {
  switch (kind) {
    case GlKind::Buffer: glDeleteBuffers(1, &name); break;
    case GlKind::Texture: glDeleteTextures(1, &name); break;
    case GlKind::Framebuffer: glDeleteFramebuffers(1, &name); break;
    case GlKind::VertexArray: glDeleteVertexArrays(1, &name); break;
    case GlKind::Shader: glDeleteShader(name); break;
    case GlKind::Program: glDeleteProgram(name); break;
    case GlKind::Query: glDeleteQueries(1, &name); break;
    case GlKind::Sampler: glDeleteSamplers(1, &name); break;
    case GlKind::Renderbuffer: glDeleteRenderbuffers(1, &name); break;
  }
  --live(kind);
}
}  // namespace detail

namespace {
// Calls a glCreate* function for one name: create(args..., 1, &name).
template <GlKind K, typename Create, typename... Args>
GlObject<K> create_one(Create create, Args... args) {
  GLuint name = 0;
  create(args..., 1, &name);
  return GlObject<K>::adopt(name);
}
}  // namespace

Buffer create_buffer() { return create_one<GlKind::Buffer>(glCreateBuffers); }
Texture create_texture(GLenum target) { return create_one<GlKind::Texture>(glCreateTextures, target); }
Framebuffer create_framebuffer() { return create_one<GlKind::Framebuffer>(glCreateFramebuffers); }
VertexArray create_vertex_array() { return create_one<GlKind::VertexArray>(glCreateVertexArrays); }
Query create_query(GLenum target) { return create_one<GlKind::Query>(glCreateQueries, target); }
Sampler create_sampler() { return create_one<GlKind::Sampler>(glCreateSamplers); }

}  // namespace atrium::gfx
