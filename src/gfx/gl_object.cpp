#include "gfx/gl_object.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "gfx/gl_features.hpp"
#include "gfx/gpu_waits.hpp"

namespace atrium::gfx {
namespace {
std::array<std::atomic<std::int64_t>, kGlKindCount> g_live{};
// Names of live buffers and textures, for the memory estimate (GL calls come
// from the context's one thread).
std::unordered_set<GLuint> g_buffers, g_textures;

std::unordered_set<GLuint>* tracked(GlKind kind) {
  if (kind == GlKind::Buffer) return &g_buffers;
  if (kind == GlKind::Texture) return &g_textures;
  return nullptr;
}

std::uint64_t texture_bytes(GLuint texture) {
  GLint levels = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  std::uint64_t bytes = 0;
  for (GLint level = 0; level < std::max(levels, 1); ++level) {
    GLint width = 0, height = 0, depth = 0, bits = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &width);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &height);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_DEPTH, &depth);
    for (GLenum size : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
                        GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE}) {
      GLint channel = 0;
      glGetTextureLevelParameteriv(texture, level, size, &channel);
      bits += channel;
    }
    bytes += static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(std::max(height, 1)) *
             static_cast<std::uint64_t>(std::max(depth, 1)) * static_cast<std::uint64_t>(bits) / 8;
  }
  return bytes;
}

// at(): a GlKind holds any byte, and without the bound GCC 12 warns of a write
// past the array.
std::atomic<std::int64_t>& live(GlKind kind) { return g_live.at(static_cast<std::size_t>(kind)); }
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

std::uint64_t estimated_gpu_memory_bytes() {
  std::uint64_t bytes = 0;
  for (GLuint buffer : g_buffers) {
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &size);
    bytes += static_cast<std::uint64_t>(size);
  }
  for (GLuint texture : g_textures) bytes += texture_bytes(texture);
  return bytes;
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
void count_created(GlKind kind, GLuint name) {
  ++live(kind);
  if (auto* names = tracked(kind)) names->insert(name);
}

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
  if (auto* names = tracked(kind)) names->erase(name);
}
}  // namespace detail

namespace {
// Whether the GPU has passed `sync`, asked without waiting (timeout 0; `flags`
// GL_SYNC_FLUSH_COMMANDS_BIT submits it if it was not yet).
bool sync_passed(GLsync sync, GLbitfield flags) {
  // Asked twice before it counts as not passed: zink 25.0.7 (over lavapipe)
  // answered a signalled fence's first query with GL_TIMEOUT_EXPIRED and the
  // next one with GL_ALREADY_SIGNALED.
  for (int ask = 0; ask < 2; ++ask) {
    const GLenum status = glClientWaitSync(sync, flags, 0);
    if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED) return true;
  }
  return false;
}

// Calls a glCreate* function for one name: create(args..., 1, &name).
template <GlKind K, typename Create, typename... Args>
GlObject<K> create_one(Create create, Args... args) {
  GLuint name = 0;
  create(args..., 1, &name);
  return GlObject<K>::adopt(name);
}
}  // namespace

Buffer create_buffer() { return create_one<GlKind::Buffer>(glCreateBuffers); }
Buffer create_index_buffer() {
  Buffer buffer = create_buffer();
  // ES has a vertex array 0 to bind it on; desktop core profiles do not (and
  // have no such rule).
  if (gl_features().es) {
    GLint vertex_array = 0;
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array);
    glBindVertexArray(0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindVertexArray(static_cast<GLuint>(vertex_array));
  }
  return buffer;
}
Texture create_texture(GLenum target) { return create_one<GlKind::Texture>(glCreateTextures, target); }
Framebuffer create_framebuffer() { return create_one<GlKind::Framebuffer>(glCreateFramebuffers); }
VertexArray create_vertex_array() { return create_one<GlKind::VertexArray>(glCreateVertexArrays); }
Query create_query(GLenum target) {
  // Mesa 22.3 refuses glCreateQueries for pipeline-statistics targets
  // (GL_INVALID_ENUM) yet counts them when begun; such a name comes from
  // glGenQueries and takes its target at the first glBeginQuery.
  if (target == GL_FRAGMENT_SHADER_INVOCATIONS_ARB) return create_one<GlKind::Query>(glGenQueries);
  return create_one<GlKind::Query>(glCreateQueries, target);
}
Sampler create_sampler() { return create_one<GlKind::Sampler>(glCreateSamplers); }

Texture create_render_target(GLenum format, int width, int height, int samples) {
  // 16-bit normalised targets are desktop GL's (ES and WebGL2 have them only
  // by extension): half floats hold the same [0, 1] values, less precisely.
  if (format == GL_RGBA16 && !gl_features().norm16_targets) format = GL_RGBA16F;
  if (samples > 1) {
    Texture texture = create_texture(GL_TEXTURE_2D_MULTISAMPLE);
    glTextureStorage2DMultisample(texture.id(), samples, format, width, height, GL_TRUE);
    return texture;
  }
  Texture texture = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.id(), 1, format, width, height);
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

void require_complete(GLuint framebuffer, std::string_view what) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  char hex[16];
  std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>(status));
  const char* why = gl_features().float_targets ? "" : "; this context cannot render to float targets (EXT_color_buffer_float)";
  throw std::runtime_error("render target " + std::string(what) + " is incomplete (status 0x" + hex + ")" + why);
}

void Fence::place() {
  reset();
  sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

void Fence::wait() {
  if (wait_uncounted()) count_gpu_wait();
}

bool Fence::wait_uncounted() {
  if (!sync_) return false;
  const bool waited = !sync_passed(sync_, 0);
  // The flush submits the fence if it was not yet. A GPU that has not passed
  // it in ten seconds is hung or lost: the caller goes on rather than freeze.
  for (int second = 0; waited && second < 10; ++second) {
    if (glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000) != GL_TIMEOUT_EXPIRED) break;
  }
  reset();
  return waited;
}

bool Fence::passed() const {
  return sync_ && sync_passed(sync_, GL_SYNC_FLUSH_COMMANDS_BIT);
}

void Fence::reset() {
  if (sync_) glDeleteSync(std::exchange(sync_, nullptr));
}

}  // namespace atrium::gfx
