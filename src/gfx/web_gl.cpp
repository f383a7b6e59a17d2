// libepoxy's dispatch table for the WebAssembly build. The engine calls GL
// through epoxy's names on every platform (gfx/gl.hpp); here no libepoxy
// exists, so this file defines the table itself and fills it from the
// browser's WebGL2 the way a GL loader does (emscripten_webgl_get_proc_address).
// Entry points WebGL2 lacks stay null until adopt_current_context routes them
// to gfx/gl_emulation.cpp; those the tier never reaches (compute, storage,
// indirect draws) stay null.
#include <cstdint>
#include <cstring>
#include <string>

#include <emscripten/emscripten.h>
#include <emscripten/html5_webgl.h>

#include "gfx/gl.hpp"

// Every GL entry point the engine names, as epoxy spells them.
#define ATRIUM_GL_ENTRY_POINTS(X) \
  X(glActiveTexture) X(glAttachShader) X(glBeginQuery) X(glBindBuffer) X(glBindBufferBase) X(glBindBufferRange) X(glBindFramebuffer) \
  X(glBindImageTexture) X(glBindSampler) X(glBindSamplers) X(glBindTexture) X(glBindTextureUnit) X(glBindTextures) \
  X(glBindVertexArray) X(glBlendFunc) X(glBlitFramebuffer) X(glBlitNamedFramebuffer) X(glBufferData) \
  X(glBufferSubData) X(glCheckFramebufferStatus) X(glCheckNamedFramebufferStatus) X(glClear) X(glClearBufferfi) \
  X(glClearBufferfv) X(glClearBufferiv) X(glClearBufferuiv) X(glClearNamedBufferData) X(glClearNamedBufferSubData) \
  X(glClearNamedFramebufferfi) X(glClearNamedFramebufferfv) X(glClearNamedFramebufferuiv) X(glClearTexImage) \
  X(glClientWaitSync) X(glClipControl) X(glColorMask) X(glCompileShader) X(glCompressedTexSubImage2D) \
  X(glCompressedTextureSubImage2D) X(glCopyBufferSubData) X(glCopyNamedBufferSubData) X(glCreateBuffers) \
  X(glCreateFramebuffers) X(glCreateProgram) X(glCreateQueries) X(glCreateSamplers) X(glCreateShader) \
  X(glCreateTextures) X(glCreateVertexArrays) X(glCullFace) X(glDebugMessageCallback) X(glDebugMessageCallbackKHR) \
  X(glDebugMessageControl) X(glDebugMessageControlKHR) X(glDeleteBuffers) X(glDeleteFramebuffers) X(glDeleteProgram) \
  X(glDeleteQueries) X(glDeleteRenderbuffers) X(glDeleteSamplers) X(glDeleteShader) X(glDeleteSync) \
  X(glDeleteTextures) X(glDeleteVertexArrays) X(glDepthFunc) X(glDepthMask) X(glDetachShader) X(glDisable) \
  X(glDisableVertexAttribArray) X(glDispatchCompute) X(glDispatchComputeIndirect) X(glDrawArrays) \
  X(glDrawArraysInstanced) X(glDrawBuffers) X(glDrawElements) X(glDrawElementsInstanced) \
  X(glDrawElementsInstancedBaseVertex) X(glEnable) X(glEnableVertexArrayAttrib) X(glEnableVertexAttribArray) \
  X(glEndQuery) X(glFenceSync) X(glFinish) X(glFlush) X(glFramebufferTexture) X(glFramebufferTexture2D) X(glFrontFace) \
  X(glGenBuffers) X(glGenFramebuffers) X(glGenQueries) X(glGenSamplers) X(glGenTextures) X(glGenVertexArrays) \
  X(glGenerateMipmap) X(glGenerateTextureMipmap) X(glGetBufferParameteri64v) X(glGetBufferSubData) X(glGetError) X(glGetInteger64v) \
  X(glGetIntegerv) X(glGetNamedBufferParameteri64v) X(glGetNamedBufferSubData) X(glGetProgramInfoLog) \
  X(glGetProgramiv) X(glGetQueryObjectiv) X(glGetQueryObjectui64v) X(glGetShaderInfoLog) X(glGetShaderiv) \
  X(glGetString) X(glGetTexImage) X(glGetTexLevelParameteriv) X(glGetTexParameteriv) X(glGetTextureHandleARB) X(glGetTextureImage) \
  X(glGetTextureLevelParameteriv) X(glGetTextureParameteriv) X(glGetTextureSamplerHandleARB) X(glGetUniformBlockIndex) X(glGetUniformLocation) \
  X(glIsBuffer) X(glIsFramebuffer) X(glIsProgram) X(glIsQuery) X(glIsRenderbuffer) X(glIsSampler) X(glIsShader) \
  X(glIsTexture) X(glIsVertexArray) X(glLinkProgram) X(glMakeTextureHandleResidentARB) X(glMapBufferRange) X(glMapNamedBufferRange) X(glMemoryBarrier) \
  X(glMultiDrawElementsIndirect) X(glMultiDrawElementsIndirectCountARB) X(glNamedBufferData) X(glNamedBufferStorage) \
  X(glNamedBufferSubData) X(glNamedFramebufferDrawBuffer) X(glNamedFramebufferDrawBuffers) \
  X(glNamedFramebufferTexture) X(glPixelStorei) X(glPolygonOffset) X(glProgramUniform1f) X(glProgramUniform1i) \
  X(glProgramUniform1iv) X(glProgramUniform1ui) X(glProgramUniform2fv) X(glProgramUniform2uiv) X(glProgramUniform3uiv) X(glProgramUniform3fv) \
  X(glProgramUniform4fv) X(glProgramUniform4iv) X(glProgramUniformMatrix3fv) X(glProgramUniformMatrix4fv) X(glQueryCounter) \
  X(glReadBuffer) X(glReadPixels) X(glSamplerParameterf) X(glSamplerParameteri) X(glScissor) X(glShaderSource) \
  X(glStencilFunc) X(glStencilMask) X(glStencilOp) X(glStencilOpSeparate) X(glTexImage2D) X(glTexImage2DMultisample) \
  X(glTexParameteri) X(glTexParameteriv) X(glTexStorage2D) X(glTexStorage2DMultisample) X(glTexSubImage2D) \
  X(glTextureParameteri) X(glTextureParameteriv) X(glTextureStorage2D) X(glTextureStorage2DMultisample) \
  X(glTextureSubImage2D) X(glUniform1f) X(glUniform1i) X(glUniform1iv) X(glUniform1ui) X(glUniform2fv) \
  X(glUniform2uiv) X(glUniform3uiv) X(glUniform3fv) X(glUniform4fv) X(glUniform4iv) X(glUniformBlockBinding) X(glUniformMatrix3fv) \
  X(glUniformMatrix4fv) X(glUnmapBuffer) X(glUnmapNamedBuffer) X(glUseProgram) X(glVertexArrayAttribBinding) \
  X(glVertexArrayAttribFormat) X(glVertexArrayAttribIFormat) X(glVertexArrayBindingDivisor) \
  X(glVertexArrayElementBuffer) X(glVertexArrayVertexBuffer) X(glVertexAttribDivisor) X(glVertexAttribI4ui) \
  X(glVertexAttribIPointer) X(glVertexAttribPointer) X(glViewport)

extern "C" {
#define ATRIUM_DEFINE_ENTRY_POINT(name) decltype(epoxy_##name) epoxy_##name = nullptr;
ATRIUM_GL_ENTRY_POINTS(ATRIUM_DEFINE_ENTRY_POINT)
#undef ATRIUM_DEFINE_ENTRY_POINT

bool epoxy_is_desktop_gl(void) { return false; }

// "OpenGL ES 3.0 (WebGL 2.0 ...)": 30.
int epoxy_gl_version(void) {
  const auto* version = reinterpret_cast<const char*>(epoxy_glGetString ? epoxy_glGetString(GL_VERSION) : nullptr);
  const char* digits = version ? std::strpbrk(version, "0123456789") : nullptr;
  if (!digits || !digits[0] || digits[1] != '.' || !digits[2]) return 0;
  return (digits[0] - '0') * 10 + (digits[2] - '0');
}

// WebGL names its extensions without the GL_ prefix the engine asks with.
bool epoxy_has_gl_extension(const char* extension) {
  const std::string name = std::strncmp(extension, "GL_", 3) == 0 ? extension + 3 : extension;
  return emscripten_webgl_enable_extension(emscripten_webgl_get_current_context(), name.c_str());
}
}

namespace atrium::gfx {
namespace {

decltype(epoxy_glGetString) g_webgl_get_string = nullptr;

// WebGL masks GL_RENDERER as "WebKit WebGL"; WEBGL_debug_renderer_info has the
// real one ("ANGLE (..., SwiftShader Device ...)"), which says what draws and
// whether it is a software renderer (gfx/limits.hpp).
const GLubyte* GLAPIENTRY get_string(GLenum name) {
  if (name != GL_RENDERER) return g_webgl_get_string(name);
  static const auto* renderer = reinterpret_cast<const char*>(static_cast<std::uintptr_t>(EM_ASM_INT({
    var info = GLctx.getExtension("WEBGL_debug_renderer_info");
    var name = String(info ? GLctx.getParameter(info.UNMASKED_RENDERER_WEBGL) : GLctx.getParameter(GLctx.RENDERER));
    var bytes = lengthBytesUTF8(name) + 1;
    var text = _malloc(bytes);
    stringToUTF8(name, text, bytes);
    return text;
  })));
  return reinterpret_cast<const GLubyte*>(renderer);
}

}  // namespace

void load_entry_points() {
#define ATRIUM_LOAD_ENTRY_POINT(name) \
  epoxy_##name = reinterpret_cast<decltype(epoxy_##name)>(emscripten_webgl_get_proc_address(#name));
  ATRIUM_GL_ENTRY_POINTS(ATRIUM_LOAD_ENTRY_POINT)
#undef ATRIUM_LOAD_ENTRY_POINT
  // WebGL2 asks for query results unsigned only, and its 64-bit ones come
  // through the timer-query extension.
  epoxy_glGetQueryObjectiv =
      reinterpret_cast<decltype(epoxy_glGetQueryObjectiv)>(emscripten_webgl_get_proc_address("glGetQueryObjectuiv"));
  epoxy_glGetQueryObjectui64v =
      reinterpret_cast<decltype(epoxy_glGetQueryObjectui64v)>(emscripten_webgl_get_proc_address("glGetQueryObjectui64vEXT"));
  g_webgl_get_string = epoxy_glGetString;
  epoxy_glGetString = get_string;
}

}  // namespace atrium::gfx
