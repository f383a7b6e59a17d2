// Move-only RAII owners of GL object names, one alias per kind. Every owner counts
// itself in a per-kind live counter, so tests can prove that create/destroy cycles
// and mode switches leave no GL objects behind.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <utility>

#include "gfx/gl.hpp"

namespace atrium::gfx {

enum class GlKind : std::uint8_t { Buffer, Texture, Framebuffer, VertexArray, Shader, Program, Query, Sampler, Renderbuffer };
inline constexpr std::size_t kGlKindCount = 9;

[[nodiscard]] std::string_view gl_kind_name(GlKind kind);
// Names currently owned by GlObject wrappers, per kind and in total.
[[nodiscard]] std::int64_t live_gl_objects(GlKind kind);
[[nodiscard]] std::int64_t live_gl_objects();
// Asks the driver (glIs*) whether a name still denotes an object of that kind.
[[nodiscard]] bool gl_object_exists(GlKind kind, GLuint name);
// The storage of every live buffer and texture owned by a wrapper, in bytes, as
// the driver reports it (buffer sizes; texel bits per level and layer). An
// estimate: drivers add padding, compression and their own allocations.
[[nodiscard]] std::uint64_t estimated_gpu_memory_bytes();

namespace detail {
void count_created(GlKind kind, GLuint name);
void destroy_gl_object(GlKind kind, GLuint name);
}  // namespace detail

template <GlKind K>
class GlObject {
 public:
  GlObject() = default;
  // Takes ownership of a name created elsewhere (glCreateShader, glCreateProgram...).
  static GlObject adopt(GLuint name) {
    GlObject object;
    object.name_ = name;
    if (name != 0) detail::count_created(K, name);
    return object;
  }
  ~GlObject() { reset(); }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }

  [[nodiscard]] GLuint id() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_ != 0) detail::destroy_gl_object(K, std::exchange(name_, 0));
  }

 private:
  GLuint name_ = 0;
};

using Buffer = GlObject<GlKind::Buffer>;
using Texture = GlObject<GlKind::Texture>;
using Framebuffer = GlObject<GlKind::Framebuffer>;
using VertexArray = GlObject<GlKind::VertexArray>;
using Shader = GlObject<GlKind::Shader>;
using Program = GlObject<GlKind::Program>;
using Query = GlObject<GlKind::Query>;
using Sampler = GlObject<GlKind::Sampler>;

// A sync object placed in the command stream (glFenceSync), deleted with its
// owner. Sync objects have no names, so they are not counted with the others.
class Fence {
 public:
  Fence() = default;
  ~Fence() { reset(); }
  Fence(const Fence&) = delete;
  Fence& operator=(const Fence&) = delete;
  Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
  Fence& operator=(Fence&& other) noexcept {
    if (this != &other) {
      reset();
      sync_ = std::exchange(other.sync_, nullptr);
    }
    return *this;
  }
  // After every command submitted so far (replacing the fence before).
  void place();
  // Until the GPU has passed it (at once when none is placed): a wait, counted
  // (gfx/gpu_waits.hpp), unless it has passed already. Leaves none placed.
  void wait();
  // The same wait, not counted (gfx/frame_pacer.hpp): whether it had to wait.
  bool wait_uncounted();
  // Whether the GPU has passed it, asked without waiting (false when none is
  // placed). Submits it if it was not yet, so that a fence asked about again
  // and again passes without anything else flushing.
  [[nodiscard]] bool passed() const;
  [[nodiscard]] bool placed() const { return sync_ != nullptr; }
  void reset();

 private:
  GLsync sync_ = nullptr;
};

// Creation through GL 4.5 direct state access.
[[nodiscard]] Buffer create_buffer();
// A buffer of vertex indices. WebGL2 fixes a buffer's kind at its first bind
// and never lets data buffers hold indices, so on ES (where edits bind to
// GL_COPY_WRITE_BUFFER) its first bind is to GL_ELEMENT_ARRAY_BUFFER.
[[nodiscard]] Buffer create_index_buffer();
[[nodiscard]] Texture create_texture(GLenum target);
[[nodiscard]] Framebuffer create_framebuffer();
[[nodiscard]] VertexArray create_vertex_array();
[[nodiscard]] Query create_query(GLenum target);
[[nodiscard]] Sampler create_sampler();

// A one-level 2D texture to render into and read back texel by texel: nearest
// filtering, edges clamped.
// GL_RGBA16 becomes GL_RGBA16F where the context cannot render to it.
// With samples > 1 a GL_TEXTURE_2D_MULTISAMPLE texture (fixed sample locations:
// every target of a framebuffer must agree).
[[nodiscard]] Texture create_render_target(GLenum format, int width, int height, int samples = 1);
// Throws std::runtime_error "render target WHAT is incomplete (status 0x...)"
// when the framebuffer cannot be drawn to.
void require_complete(GLuint framebuffer, std::string_view what);

}  // namespace atrium::gfx
