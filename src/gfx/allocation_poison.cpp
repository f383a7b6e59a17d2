#include "gfx/allocation_poison.hpp"

#include "gfx/gl.hpp"

namespace atrium::gfx {
namespace {

bool g_poison = false;
// The entry points the wrappers stand in front of: the driver's (or, until
// its first call, libepoxy's resolving stub), or gl_emulation's.
decltype(epoxy_glNamedBufferStorage) g_storage = nullptr;
decltype(epoxy_glNamedBufferData) g_data = nullptr;

// Calls `next` through its slot: libepoxy's stub resolves the driver's entry
// point only when it finds itself in the slot (and otherwise calls whatever
// the slot holds, here the wrapper again), so the slot holds `next` for the
// call, which keeps what the stub put there, and the wrapper after it.
template <typename Fn, typename... Args>
void call_through(Fn& slot, Fn& next, Fn wrapper, Args... args) {
  slot = next;
  slot(args...);
  next = slot;
  slot = wrapper;
}

void poison(GLuint buffer) {
  glClearNamedBufferData(buffer, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &kPoisonWord);
}

void GLAPIENTRY poisoned_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags) {
  call_through(epoxy_glNamedBufferStorage, g_storage, poisoned_storage, buffer, size, data, flags);
  // A size that is not a whole number of words cannot be cleared as R32UI.
  if (!data && size % 4 == 0) poison(buffer);
}

void GLAPIENTRY poisoned_data(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage) {
  call_through(epoxy_glNamedBufferData, g_data, poisoned_data, buffer, size, data, usage);
  if (!data && size % 4 == 0) poison(buffer);
}

}  // namespace

void set_allocation_poison(bool on) { g_poison = on; }

void route_allocation_poison(bool direct_state_access) {
  // gl_emulation has just pointed these at the driver or its emulation; with
  // poisoning the wrappers go in front of whichever it chose.
  if (!g_poison || !direct_state_access) return;
  g_storage = epoxy_glNamedBufferStorage;
  g_data = epoxy_glNamedBufferData;
  epoxy_glNamedBufferStorage = poisoned_storage;
  epoxy_glNamedBufferData = poisoned_data;
}

}  // namespace atrium::gfx
