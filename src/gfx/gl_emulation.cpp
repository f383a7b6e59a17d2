#include "gfx/gl_emulation.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "gfx/gl.hpp"

namespace atrium::gfx {
namespace {

// ---- what DSA keeps in the object and a bind-to-edit context does not say ----

enum class TexelKind : std::uint8_t { Float, Int, Uint, Depth, DepthStencil };

// An internal format with the client format and type that describe it (for
// glTexImage2D without glTexStorage, read-backs and clears) and its bits per
// channel (red, green, blue, alpha, depth, stencil) for level queries.
struct FormatInfo {
  GLenum internal_format;
  GLenum format;
  GLenum type;
  int bytes;
  TexelKind kind;
  std::array<int, 6> bits;
};

constexpr std::array kFormats{
    FormatInfo{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, TexelKind::Float, {8, 8, 8, 8, 0, 0}},
    FormatInfo{GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, TexelKind::Float, {8, 8, 8, 8, 0, 0}},
    FormatInfo{GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2, TexelKind::Float, {8, 8, 0, 0, 0, 0}},
    FormatInfo{GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, TexelKind::Float, {8, 0, 0, 0, 0, 0}},
    FormatInfo{GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, 8, TexelKind::Float, {16, 16, 16, 16, 0, 0}},
    FormatInfo{GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4, TexelKind::Float, {10, 10, 10, 2, 0, 0}},
    FormatInfo{GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, 4, TexelKind::Float, {11, 11, 10, 0, 0, 0}},
    FormatInfo{GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, TexelKind::Float, {16, 16, 16, 16, 0, 0}},
    FormatInfo{GL_RG16F, GL_RG, GL_HALF_FLOAT, 4, TexelKind::Float, {16, 16, 0, 0, 0, 0}},
    FormatInfo{GL_R16F, GL_RED, GL_HALF_FLOAT, 2, TexelKind::Float, {16, 0, 0, 0, 0, 0}},
    FormatInfo{GL_RGBA32F, GL_RGBA, GL_FLOAT, 16, TexelKind::Float, {32, 32, 32, 32, 0, 0}},
    FormatInfo{GL_RG32F, GL_RG, GL_FLOAT, 8, TexelKind::Float, {32, 32, 0, 0, 0, 0}},
    FormatInfo{GL_R32F, GL_RED, GL_FLOAT, 4, TexelKind::Float, {32, 0, 0, 0, 0, 0}},
    FormatInfo{GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 16, TexelKind::Uint, {32, 32, 32, 32, 0, 0}},
    FormatInfo{GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, 8, TexelKind::Uint, {32, 32, 0, 0, 0, 0}},
    FormatInfo{GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 4, TexelKind::Uint, {32, 0, 0, 0, 0, 0}},
    FormatInfo{GL_RGBA16UI, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, 8, TexelKind::Uint, {16, 16, 16, 16, 0, 0}},
    FormatInfo{GL_RG16UI, GL_RG_INTEGER, GL_UNSIGNED_SHORT, 4, TexelKind::Uint, {16, 16, 0, 0, 0, 0}},
    FormatInfo{GL_R16UI, GL_RED_INTEGER, GL_UNSIGNED_SHORT, 2, TexelKind::Uint, {16, 0, 0, 0, 0, 0}},
    FormatInfo{GL_R32I, GL_RED_INTEGER, GL_INT, 4, TexelKind::Int, {32, 0, 0, 0, 0, 0}},
    FormatInfo{GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, 8, TexelKind::DepthStencil, {0, 0, 0, 0, 32, 8}},
    FormatInfo{GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4, TexelKind::DepthStencil, {0, 0, 0, 0, 24, 8}},
    FormatInfo{GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4, TexelKind::Depth, {0, 0, 0, 0, 32, 0}},
    FormatInfo{GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 4, TexelKind::Depth, {0, 0, 0, 0, 24, 0}},
    FormatInfo{GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 2, TexelKind::Depth, {0, 0, 0, 0, 16, 0}},
};

const FormatInfo* find_format(GLenum internal_format) {
  const auto it = std::find_if(kFormats.begin(), kFormats.end(),
                               [&](const FormatInfo& f) { return f.internal_format == internal_format; });
  return it == kFormats.end() ? nullptr : &*it;
}

const FormatInfo& format_of(GLenum internal_format) {
  if (const FormatInfo* info = find_format(internal_format)) return *info;
  throw std::runtime_error("GL emulation: internal format 0x" + std::to_string(internal_format) +
                           " has no client format here (gfx/gl_emulation.cpp)");
}

// Bytes of one texel as the caller hands it over (format and type), for the
// clears, which read exactly that much.
std::size_t client_texel_bytes(GLenum format, GLenum type) {
  std::size_t components = 4;
  switch (format) {
    case GL_RED: case GL_RED_INTEGER: case GL_DEPTH_COMPONENT: components = 1; break;
    case GL_RG: case GL_RG_INTEGER: components = 2; break;
    case GL_RGB: case GL_RGB_INTEGER: components = 3; break;
    default: break;
  }
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return components;
    case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: return 2 * components;
    default: return 4 * components;
  }
}

struct TextureRecord {
  GLenum target = GL_TEXTURE_2D;
  GLenum internal_format = 0;
  GLsizei levels = 0, width = 0, height = 0, depth = 1;
};

struct AttribFormat {
  bool specified = false, integer = false, enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLboolean normalized = GL_FALSE;
  GLuint offset = 0, binding = 0;
};

struct VertexBinding {
  GLuint buffer = 0;
  GLintptr offset = 0;
  GLsizei stride = 0;
  GLuint divisor = 0;
};

constexpr GLuint kVertexSlots = 16;
struct VertexArrayRecord {
  std::array<AttribFormat, kVertexSlots> attribs{};
  std::array<VertexBinding, kVertexSlots> bindings{};
};

// GL calls come from the context's one thread.
std::unordered_map<GLuint, TextureRecord> g_textures;
std::unordered_map<GLuint, VertexArrayRecord> g_vertex_arrays;
GlFeatures g_features;

TextureRecord& texture_record(GLuint texture) { return g_textures[texture]; }

void bind_for_edit(GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + kEditUnit);
  glBindTexture(texture_record(texture).target, texture);
}

GLint current(GLenum binding) {
  GLint name = 0;
  glGetIntegerv(binding, &name);
  return name;
}

// Runs `edit` with `framebuffer` bound to `target`, then binds back what was.
template <typename Edit>
void with_framebuffer(GLenum target, GLuint framebuffer, Edit edit) {
  const GLint was = current(target == GL_READ_FRAMEBUFFER ? GL_READ_FRAMEBUFFER_BINDING : GL_DRAW_FRAMEBUFFER_BINDING);
  glBindFramebuffer(target, framebuffer);
  edit();
  glBindFramebuffer(target, static_cast<GLuint>(was));
}

template <typename Edit>
void with_program(GLuint program, Edit edit) {
  const auto was = static_cast<GLuint>(current(GL_CURRENT_PROGRAM));
  if (was != program) glUseProgram(program);
  edit();
  // A program deleted while it was in use goes once another replaces it.
  if (was != program) glUseProgram(glIsProgram(was) ? was : 0);
}

template <typename Edit>
void with_vertex_array(GLuint vertex_array, Edit edit) {
  const auto was = static_cast<GLuint>(current(GL_VERTEX_ARRAY_BINDING));
  if (was != vertex_array) glBindVertexArray(vertex_array);
  edit();
  if (was != vertex_array) glBindVertexArray(was);
}

void attach(GLenum target, GLenum attachment, GLuint texture, GLint level) {
  if (texture == 0) {
    glFramebufferTexture2D(target, attachment, GL_TEXTURE_2D, 0, 0);
    return;
  }
  const GLenum texture_target = texture_record(texture).target;
  if (texture_target == GL_TEXTURE_2D || texture_target == GL_TEXTURE_2D_MULTISAMPLE) {
    glFramebufferTexture2D(target, attachment, texture_target, texture, level);
  } else if (!g_features.es) {
    glFramebufferTexture(target, attachment, texture, level);  // layered (GL 3.2)
  } else {
    throw std::runtime_error("GL emulation: OpenGL ES 3.0 cannot attach every layer of a texture at once");
  }
}

// ---- creation ----

void GLAPIENTRY create_buffers(GLsizei n, GLuint* names) { glGenBuffers(n, names); }
void GLAPIENTRY create_framebuffers(GLsizei n, GLuint* names) { glGenFramebuffers(n, names); }
void GLAPIENTRY create_samplers(GLsizei n, GLuint* names) { glGenSamplers(n, names); }
void GLAPIENTRY create_queries(GLenum, GLsizei n, GLuint* names) { glGenQueries(n, names); }

void GLAPIENTRY create_textures(GLenum target, GLsizei n, GLuint* names) {
  glGenTextures(n, names);
  for (GLsizei i = 0; i < n; ++i) {
    g_textures[names[i]] = TextureRecord{.target = target};
    bind_for_edit(names[i]);  // the first bind gives the name its target
  }
}

void GLAPIENTRY create_vertex_arrays(GLsizei n, GLuint* names) {
  glGenVertexArrays(n, names);
  for (GLsizei i = 0; i < n; ++i) g_vertex_arrays[names[i]] = VertexArrayRecord{};
}

// ---- buffers ----

void GLAPIENTRY named_buffer_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags) {
  if (flags & GL_MAP_PERSISTENT_BIT) {
    throw std::runtime_error("GL emulation: a persistently mapped buffer needs OpenGL 4.4 (ARB_buffer_storage)");
  }
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  glBufferData(GL_COPY_WRITE_BUFFER, size, data, (flags & GL_MAP_READ_BIT) ? GL_STREAM_READ : GL_DYNAMIC_DRAW);
}

void GLAPIENTRY named_buffer_data(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  glBufferData(GL_COPY_WRITE_BUFFER, size, data, usage);
}

void GLAPIENTRY named_buffer_sub_data(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  glBufferSubData(GL_COPY_WRITE_BUFFER, offset, size, data);
}

void GLAPIENTRY clear_named_buffer_sub_data(GLuint buffer, GLenum internal_format, GLintptr offset, GLsizeiptr size,
                                            GLenum format, GLenum type, const void* data) {
  const auto element = static_cast<std::size_t>(format_of(internal_format).bytes);
  std::vector<unsigned char> fill(static_cast<std::size_t>(size), 0);
  if (data) {
    const std::size_t given = std::min(element, client_texel_bytes(format, type));
    for (std::size_t at = 0; at + element <= fill.size(); at += element) std::memcpy(fill.data() + at, data, given);
  }
  named_buffer_sub_data(buffer, offset, size, fill.data());
}

void GLAPIENTRY get_named_buffer_parameteri64v(GLuint buffer, GLenum name, GLint64* value) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  glGetBufferParameteri64v(GL_COPY_WRITE_BUFFER, name, value);
}

void GLAPIENTRY clear_named_buffer_data(GLuint buffer, GLenum internal_format, GLenum format, GLenum type, const void* data) {
  GLint64 size = 0;
  get_named_buffer_parameteri64v(buffer, GL_BUFFER_SIZE, &size);
  clear_named_buffer_sub_data(buffer, internal_format, 0, static_cast<GLsizeiptr>(size), format, type, data);
}

void GLAPIENTRY copy_named_buffer_sub_data(GLuint from, GLuint to, GLintptr from_offset, GLintptr to_offset, GLsizeiptr size) {
  glBindBuffer(GL_COPY_READ_BUFFER, from);
  glBindBuffer(GL_COPY_WRITE_BUFFER, to);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, from_offset, to_offset, size);
}

void* GLAPIENTRY map_named_buffer_range(GLuint buffer, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  return glMapBufferRange(GL_COPY_WRITE_BUFFER, offset, length, access);
}

GLboolean GLAPIENTRY unmap_named_buffer(GLuint buffer) {
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
  return glUnmapBuffer(GL_COPY_WRITE_BUFFER);
}

void GLAPIENTRY get_named_buffer_sub_data(GLuint buffer, GLintptr offset, GLsizeiptr size, void* data) {
  glBindBuffer(GL_COPY_READ_BUFFER, buffer);
  if (g_features.read_buffers) {
    glGetBufferSubData(GL_COPY_READ_BUFFER, offset, size, data);
    return;
  }
  const void* mapped = glMapBufferRange(GL_COPY_READ_BUFFER, offset, size, GL_MAP_READ_BIT);
  if (mapped) std::memcpy(data, mapped, static_cast<std::size_t>(size));
  glUnmapBuffer(GL_COPY_READ_BUFFER);
}

// ---- textures ----

void GLAPIENTRY texture_storage_2d(GLuint texture, GLsizei levels, GLenum internal_format, GLsizei width, GLsizei height) {
  TextureRecord& record = texture_record(texture);
  record.internal_format = internal_format;
  record.levels = levels;
  record.width = width;
  record.height = height;
  bind_for_edit(texture);
  if (g_features.texture_storage) {
    glTexStorage2D(record.target, levels, internal_format, width, height);
    return;
  }
  const FormatInfo& info = format_of(internal_format);
  for (GLsizei level = 0; level < levels; ++level) {
    glTexImage2D(record.target, level, static_cast<GLint>(internal_format), std::max(1, width >> level),
                 std::max(1, height >> level), 0, info.format, info.type, nullptr);
  }
  glTexParameteri(record.target, GL_TEXTURE_MAX_LEVEL, levels - 1);
}

void GLAPIENTRY texture_storage_2d_multisample(GLuint texture, GLsizei samples, GLenum internal_format, GLsizei width,
                                               GLsizei height, GLboolean fixed_locations) {
  if (!g_features.multisample_textures) {
    throw std::runtime_error("GL emulation: multisampled textures need OpenGL 3.2 or OpenGL ES 3.1");
  }
  TextureRecord& record = texture_record(texture);
  record.internal_format = internal_format;
  record.levels = 1;
  record.width = width;
  record.height = height;
  bind_for_edit(texture);
  if (g_features.es) glTexStorage2DMultisample(record.target, samples, internal_format, width, height, fixed_locations);
  else glTexImage2DMultisample(record.target, samples, internal_format, width, height, fixed_locations);
}

void GLAPIENTRY texture_parameteri(GLuint texture, GLenum name, GLint value) {
  bind_for_edit(texture);
  glTexParameteri(texture_record(texture).target, name, value);
}

void GLAPIENTRY texture_parameteriv(GLuint texture, GLenum name, const GLint* values) {
  bind_for_edit(texture);
  glTexParameteriv(texture_record(texture).target, name, values);
}

void GLAPIENTRY get_texture_parameteriv(GLuint texture, GLenum name, GLint* values) {
  bind_for_edit(texture);
  glGetTexParameteriv(texture_record(texture).target, name, values);
}

void GLAPIENTRY get_texture_level_parameteriv(GLuint texture, GLint level, GLenum name, GLint* value) {
  if (g_features.level_queries) {
    bind_for_edit(texture);
    glGetTexLevelParameteriv(texture_record(texture).target, level, name, value);
    return;
  }
  // ES 3.0 cannot ask: answer from what the texture was made with.
  const TextureRecord& record = texture_record(texture);
  const FormatInfo* info = find_format(record.internal_format);
  const bool exists = level < record.levels;
  const auto channel = [&](int i) { return exists && info ? info->bits[static_cast<std::size_t>(i)] : 0; };
  switch (name) {
    case GL_TEXTURE_WIDTH: *value = exists ? std::max(1, record.width >> level) : 0; break;
    case GL_TEXTURE_HEIGHT: *value = exists ? std::max(1, record.height >> level) : 0; break;
    case GL_TEXTURE_DEPTH: *value = exists ? record.depth : 0; break;
    case GL_TEXTURE_INTERNAL_FORMAT: *value = static_cast<GLint>(record.internal_format); break;
    case GL_TEXTURE_RED_SIZE: *value = channel(0); break;
    case GL_TEXTURE_GREEN_SIZE: *value = channel(1); break;
    case GL_TEXTURE_BLUE_SIZE: *value = channel(2); break;
    case GL_TEXTURE_ALPHA_SIZE: *value = channel(3); break;
    case GL_TEXTURE_DEPTH_SIZE: *value = channel(4); break;
    case GL_TEXTURE_STENCIL_SIZE: *value = channel(5); break;
    default: *value = 0; break;
  }
}

void GLAPIENTRY texture_sub_image_2d(GLuint texture, GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                                     GLenum format, GLenum type, const void* pixels) {
  bind_for_edit(texture);
  glTexSubImage2D(texture_record(texture).target, level, x, y, width, height, format, type, pixels);
}

void GLAPIENTRY compressed_texture_sub_image_2d(GLuint texture, GLint level, GLint x, GLint y, GLsizei width, GLsizei height,
                                                GLenum format, GLsizei bytes, const void* data) {
  bind_for_edit(texture);
  glCompressedTexSubImage2D(texture_record(texture).target, level, x, y, width, height, format, bytes, data);
}

void GLAPIENTRY generate_texture_mipmap(GLuint texture) {
  bind_for_edit(texture);
  glGenerateMipmap(texture_record(texture).target);
}

void GLAPIENTRY bind_texture_unit(GLuint unit, GLuint texture) {
  glActiveTexture(GL_TEXTURE0 + unit);
  if (texture != 0) {
    glBindTexture(texture_record(texture).target, texture);
    return;
  }
  // DSA's unbind empties every target of the unit.
  for (GLenum target : {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D}) glBindTexture(target, 0);
  if (g_features.multisample_textures) glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
}

void GLAPIENTRY bind_textures(GLuint first, GLsizei count, const GLuint* textures) {
  for (GLsizei i = 0; i < count; ++i) bind_texture_unit(first + static_cast<GLuint>(i), textures ? textures[i] : 0);
}

void GLAPIENTRY bind_samplers(GLuint first, GLsizei count, const GLuint* samplers) {
  for (GLsizei i = 0; i < count; ++i) glBindSampler(first + static_cast<GLuint>(i), samplers ? samplers[i] : 0);
}

// Level `level` of a colour texture through a read framebuffer.
template <typename Read>
void with_texture_read(GLuint texture, GLint level, Read read) {
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  with_framebuffer(GL_READ_FRAMEBUFFER, framebuffer, [&] {
    attach(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture, level);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    read();
  });
  glDeleteFramebuffers(1, &framebuffer);
}

void GLAPIENTRY get_texture_image(GLuint texture, GLint level, GLenum format, GLenum type, GLsizei, void* pixels) {
  const TextureRecord& record = texture_record(texture);
  if (!g_features.es) {
    bind_for_edit(texture);
    glGetTexImage(record.target, level, format, type, pixels);
    return;
  }
  if (format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL) {
    throw std::runtime_error("GL emulation: OpenGL ES 3.0 cannot read depth textures back");
  }
  with_texture_read(texture, level, [&] {
    glReadPixels(0, 0, std::max(1, record.width >> level), std::max(1, record.height >> level), format, type, pixels);
  });
}

void GLAPIENTRY clear_tex_image(GLuint texture, GLint level, GLenum format, GLenum type, const void* data) {
  const TextureRecord& record = texture_record(texture);
  const FormatInfo& info = format_of(record.internal_format);
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] {
    std::array<std::uint32_t, 4> zero{};
    const void* value = data ? data : zero.data();
    switch (info.kind) {
      case TexelKind::Depth:
        attach(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture, level);
        glClearBufferfv(GL_DEPTH, 0, static_cast<const GLfloat*>(value));
        break;
      case TexelKind::DepthStencil:
        attach(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, texture, level);
        glClearBufferfi(GL_DEPTH_STENCIL, 0, *static_cast<const GLfloat*>(value), 0);
        break;
      default: {
        attach(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture, level);
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0};
        glDrawBuffers(1, buffers);
        // Channels the caller's texel leaves out clear to zero.
        std::array<std::uint32_t, 4> texel{};
        std::memcpy(texel.data(), value, data ? std::min(client_texel_bytes(format, type), sizeof(texel)) : sizeof(texel));
        if (info.kind == TexelKind::Uint) glClearBufferuiv(GL_COLOR, 0, texel.data());
        else if (info.kind == TexelKind::Int) glClearBufferiv(GL_COLOR, 0, reinterpret_cast<const GLint*>(texel.data()));
        else if (!data || type == GL_FLOAT) glClearBufferfv(GL_COLOR, 0, reinterpret_cast<const GLfloat*>(texel.data()));
        else throw std::runtime_error("GL emulation: glClearTexImage of a float target takes GL_FLOAT texels here");
      }
    }
  });
  glDeleteFramebuffers(1, &framebuffer);
}

// ---- framebuffers ----

void GLAPIENTRY named_framebuffer_texture(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level) {
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { attach(GL_DRAW_FRAMEBUFFER, attachment, texture, level); });
}

void GLAPIENTRY named_framebuffer_draw_buffers(GLuint framebuffer, GLsizei count, const GLenum* buffers) {
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { glDrawBuffers(count, buffers); });
}

void GLAPIENTRY named_framebuffer_draw_buffer(GLuint framebuffer, GLenum buffer) {
  named_framebuffer_draw_buffers(framebuffer, 1, &buffer);
}

void GLAPIENTRY clear_named_framebufferfv(GLuint framebuffer, GLenum buffer, GLint draw_buffer, const GLfloat* value) {
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { glClearBufferfv(buffer, draw_buffer, value); });
}

void GLAPIENTRY clear_named_framebufferuiv(GLuint framebuffer, GLenum buffer, GLint draw_buffer, const GLuint* value) {
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { glClearBufferuiv(buffer, draw_buffer, value); });
}

void GLAPIENTRY clear_named_framebufferfi(GLuint framebuffer, GLenum buffer, GLint draw_buffer, GLfloat depth, GLint stencil) {
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { glClearBufferfi(buffer, draw_buffer, depth, stencil); });
}

void GLAPIENTRY blit_named_framebuffer(GLuint from, GLuint to, GLint x0, GLint y0, GLint x1, GLint y1, GLint u0, GLint v0,
                                       GLint u1, GLint v1, GLbitfield mask, GLenum filter) {
  with_framebuffer(GL_READ_FRAMEBUFFER, from, [&] {
    with_framebuffer(GL_DRAW_FRAMEBUFFER, to, [&] { glBlitFramebuffer(x0, y0, x1, y1, u0, v0, u1, v1, mask, filter); });
  });
}

GLenum GLAPIENTRY check_named_framebuffer_status(GLuint framebuffer, GLenum) {
  GLenum status = 0;
  with_framebuffer(GL_DRAW_FRAMEBUFFER, framebuffer, [&] { status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER); });
  return status;
}

// ---- vertex arrays: ES 3.0 has no separate attribute formats, so each
// attribute is specified again whenever its format or its buffer changes ----

void specify(GLuint vertex_array, GLuint location) {
  const VertexArrayRecord& record = g_vertex_arrays[vertex_array];
  const AttribFormat& attrib = record.attribs[location];
  const VertexBinding& binding = record.bindings[attrib.binding];
  if (!attrib.specified || binding.buffer == 0) return;
  with_vertex_array(vertex_array, [&] {
    glBindBuffer(GL_ARRAY_BUFFER, binding.buffer);
    const auto* pointer = reinterpret_cast<const void*>(static_cast<std::uintptr_t>(binding.offset) + attrib.offset);
    if (attrib.integer) glVertexAttribIPointer(location, attrib.size, attrib.type, binding.stride, pointer);
    else glVertexAttribPointer(location, attrib.size, attrib.type, attrib.normalized, binding.stride, pointer);
    glVertexAttribDivisor(location, binding.divisor);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  });
}

void specify_binding(GLuint vertex_array, GLuint binding) {
  const VertexArrayRecord& record = g_vertex_arrays[vertex_array];
  for (GLuint location = 0; location < kVertexSlots; ++location) {
    if (record.attribs[location].binding == binding) specify(vertex_array, location);
  }
}

void GLAPIENTRY vertex_array_vertex_buffer(GLuint vertex_array, GLuint binding, GLuint buffer, GLintptr offset, GLsizei stride) {
  VertexBinding& slot = g_vertex_arrays[vertex_array].bindings.at(binding);
  slot.buffer = buffer;
  slot.offset = offset;
  slot.stride = stride;
  specify_binding(vertex_array, binding);
}

void GLAPIENTRY vertex_array_binding_divisor(GLuint vertex_array, GLuint binding, GLuint divisor) {
  g_vertex_arrays[vertex_array].bindings.at(binding).divisor = divisor;
  specify_binding(vertex_array, binding);
}

void set_format(GLuint vertex_array, GLuint location, GLint size, GLenum type, GLboolean normalized, GLuint offset, bool integer) {
  AttribFormat& attrib = g_vertex_arrays[vertex_array].attribs.at(location);
  attrib.specified = true;
  attrib.integer = integer;
  attrib.size = size;
  attrib.type = type;
  attrib.normalized = normalized;
  attrib.offset = offset;
  specify(vertex_array, location);
}

void GLAPIENTRY vertex_array_attrib_format(GLuint vertex_array, GLuint location, GLint size, GLenum type, GLboolean normalized,
                                           GLuint offset) {
  set_format(vertex_array, location, size, type, normalized, offset, false);
}

void GLAPIENTRY vertex_array_attrib_iformat(GLuint vertex_array, GLuint location, GLint size, GLenum type, GLuint offset) {
  set_format(vertex_array, location, size, type, GL_FALSE, offset, true);
}

void GLAPIENTRY vertex_array_attrib_binding(GLuint vertex_array, GLuint location, GLuint binding) {
  g_vertex_arrays[vertex_array].attribs.at(location).binding = binding;
  specify(vertex_array, location);
}

void GLAPIENTRY enable_vertex_array_attrib(GLuint vertex_array, GLuint location) {
  with_vertex_array(vertex_array, [&] { glEnableVertexAttribArray(location); });
}

void GLAPIENTRY vertex_array_element_buffer(GLuint vertex_array, GLuint buffer) {
  with_vertex_array(vertex_array, [&] { glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer); });
}

// ---- program uniforms: set with the program bound, the bound one put back ----

void GLAPIENTRY program_uniform1i(GLuint p, GLint l, GLint v) { with_program(p, [&] { glUniform1i(l, v); }); }
void GLAPIENTRY program_uniform1ui(GLuint p, GLint l, GLuint v) { with_program(p, [&] { glUniform1ui(l, v); }); }
void GLAPIENTRY program_uniform1f(GLuint p, GLint l, GLfloat v) { with_program(p, [&] { glUniform1f(l, v); }); }
void GLAPIENTRY program_uniform1iv(GLuint p, GLint l, GLsizei n, const GLint* v) { with_program(p, [&] { glUniform1iv(l, n, v); }); }
void GLAPIENTRY program_uniform2uiv(GLuint p, GLint l, GLsizei n, const GLuint* v) { with_program(p, [&] { glUniform2uiv(l, n, v); }); }
void GLAPIENTRY program_uniform3uiv(GLuint p, GLint l, GLsizei n, const GLuint* v) { with_program(p, [&] { glUniform3uiv(l, n, v); }); }
void GLAPIENTRY program_uniform4iv(GLuint p, GLint l, GLsizei n, const GLint* v) { with_program(p, [&] { glUniform4iv(l, n, v); }); }
void GLAPIENTRY program_uniform2fv(GLuint p, GLint l, GLsizei n, const GLfloat* v) { with_program(p, [&] { glUniform2fv(l, n, v); }); }
void GLAPIENTRY program_uniform3fv(GLuint p, GLint l, GLsizei n, const GLfloat* v) { with_program(p, [&] { glUniform3fv(l, n, v); }); }
void GLAPIENTRY program_uniform4fv(GLuint p, GLint l, GLsizei n, const GLfloat* v) { with_program(p, [&] { glUniform4fv(l, n, v); }); }
void GLAPIENTRY program_uniform_matrix3fv(GLuint p, GLint l, GLsizei n, GLboolean t, const GLfloat* v) {
  with_program(p, [&] { glUniformMatrix3fv(l, n, t, v); });
}
void GLAPIENTRY program_uniform_matrix4fv(GLuint p, GLint l, GLsizei n, GLboolean t, const GLfloat* v) {
  with_program(p, [&] { glUniformMatrix4fv(l, n, t, v); });
}

// ---- state with no ES 3.0 / GL 4.1 counterpart ----

// Shaders compiled with CLIP_Z_MINUS_ONE_TO_ONE remap their own depth instead
// (common/frame.glsl), so the depth convention holds without it.
void GLAPIENTRY clip_control(GLenum, GLenum) {}
// Without storage writes or image stores there is nothing to make visible.
void GLAPIENTRY memory_barrier(GLbitfield) {}

// ---- routing ----

// The driver's entry point behind each slot, saved the first time it is routed.
std::unordered_map<const void*, void (*)()> g_originals;

template <typename Fn>
void route(Fn& entry, Fn emulation, bool emulate) {
  const auto [it, inserted] = g_originals.try_emplace(&entry, reinterpret_cast<void (*)()>(entry));
  entry = emulate ? emulation : reinterpret_cast<Fn>(it->second);
}

}  // namespace

void route_missing_entry_points(const GlFeatures& features) {
  g_features = features;
  g_textures.clear();
  g_vertex_arrays.clear();
  const bool dsa = !features.direct_state_access;
  route(epoxy_glCreateBuffers, create_buffers, dsa);
  route(epoxy_glCreateTextures, create_textures, dsa);
  route(epoxy_glCreateFramebuffers, create_framebuffers, dsa);
  route(epoxy_glCreateVertexArrays, create_vertex_arrays, dsa);
  route(epoxy_glCreateSamplers, create_samplers, dsa);
  route(epoxy_glCreateQueries, create_queries, dsa);
  route(epoxy_glNamedBufferStorage, named_buffer_storage, dsa);
  route(epoxy_glNamedBufferData, named_buffer_data, dsa);
  route(epoxy_glNamedBufferSubData, named_buffer_sub_data, dsa);
  route(epoxy_glClearNamedBufferData, clear_named_buffer_data, dsa);
  route(epoxy_glClearNamedBufferSubData, clear_named_buffer_sub_data, dsa);
  route(epoxy_glCopyNamedBufferSubData, copy_named_buffer_sub_data, dsa);
  route(epoxy_glMapNamedBufferRange, map_named_buffer_range, dsa);
  route(epoxy_glUnmapNamedBuffer, unmap_named_buffer, dsa);
  route(epoxy_glGetNamedBufferSubData, get_named_buffer_sub_data, dsa);
  route(epoxy_glGetNamedBufferParameteri64v, get_named_buffer_parameteri64v, dsa);
  route(epoxy_glTextureStorage2D, texture_storage_2d, dsa);
  route(epoxy_glTextureStorage2DMultisample, texture_storage_2d_multisample, dsa);
  route(epoxy_glTextureParameteri, texture_parameteri, dsa);
  route(epoxy_glTextureParameteriv, texture_parameteriv, dsa);
  route(epoxy_glGetTextureParameteriv, get_texture_parameteriv, dsa);
  route(epoxy_glGetTextureLevelParameteriv, get_texture_level_parameteriv, dsa);
  route(epoxy_glTextureSubImage2D, texture_sub_image_2d, dsa);
  route(epoxy_glCompressedTextureSubImage2D, compressed_texture_sub_image_2d, dsa);
  route(epoxy_glGenerateTextureMipmap, generate_texture_mipmap, dsa);
  route(epoxy_glBindTextureUnit, bind_texture_unit, dsa);
  route(epoxy_glGetTextureImage, get_texture_image, dsa);
  route(epoxy_glNamedFramebufferTexture, named_framebuffer_texture, dsa);
  route(epoxy_glNamedFramebufferDrawBuffers, named_framebuffer_draw_buffers, dsa);
  route(epoxy_glNamedFramebufferDrawBuffer, named_framebuffer_draw_buffer, dsa);
  route(epoxy_glClearNamedFramebufferfv, clear_named_framebufferfv, dsa);
  route(epoxy_glClearNamedFramebufferuiv, clear_named_framebufferuiv, dsa);
  route(epoxy_glClearNamedFramebufferfi, clear_named_framebufferfi, dsa);
  route(epoxy_glBlitNamedFramebuffer, blit_named_framebuffer, dsa);
  route(epoxy_glCheckNamedFramebufferStatus, check_named_framebuffer_status, dsa);
  route(epoxy_glVertexArrayVertexBuffer, vertex_array_vertex_buffer, dsa);
  route(epoxy_glVertexArrayBindingDivisor, vertex_array_binding_divisor, dsa);
  route(epoxy_glVertexArrayAttribFormat, vertex_array_attrib_format, dsa);
  route(epoxy_glVertexArrayAttribIFormat, vertex_array_attrib_iformat, dsa);
  route(epoxy_glVertexArrayAttribBinding, vertex_array_attrib_binding, dsa);
  route(epoxy_glEnableVertexArrayAttrib, enable_vertex_array_attrib, dsa);
  route(epoxy_glVertexArrayElementBuffer, vertex_array_element_buffer, dsa);

  const bool uniforms = !features.program_uniforms;
  route(epoxy_glProgramUniform1i, program_uniform1i, uniforms);
  route(epoxy_glProgramUniform1ui, program_uniform1ui, uniforms);
  route(epoxy_glProgramUniform1f, program_uniform1f, uniforms);
  route(epoxy_glProgramUniform1iv, program_uniform1iv, uniforms);
  route(epoxy_glProgramUniform2uiv, program_uniform2uiv, uniforms);
  route(epoxy_glProgramUniform3uiv, program_uniform3uiv, uniforms);
  route(epoxy_glProgramUniform4iv, program_uniform4iv, uniforms);
  route(epoxy_glProgramUniform2fv, program_uniform2fv, uniforms);
  route(epoxy_glProgramUniform3fv, program_uniform3fv, uniforms);
  route(epoxy_glProgramUniform4fv, program_uniform4fv, uniforms);
  route(epoxy_glProgramUniformMatrix3fv, program_uniform_matrix3fv, uniforms);
  route(epoxy_glProgramUniformMatrix4fv, program_uniform_matrix4fv, uniforms);

  route(epoxy_glBindTextures, bind_textures, !features.multi_bind);
  route(epoxy_glBindSamplers, bind_samplers, !features.multi_bind);
  route(epoxy_glClearTexImage, clear_tex_image, !features.clear_texture);
  route(epoxy_glClipControl, clip_control, !features.clip_control);
  route(epoxy_glMemoryBarrier, memory_barrier, !features.memory_barriers);
  // ES names KHR_debug's entry points with a suffix.
  const bool khr_debug = features.es && epoxy_has_gl_extension("GL_KHR_debug");
  route(epoxy_glDebugMessageCallback, reinterpret_cast<decltype(epoxy_glDebugMessageCallback)>(epoxy_glDebugMessageCallbackKHR),
        khr_debug);
  route(epoxy_glDebugMessageControl, reinterpret_cast<decltype(epoxy_glDebugMessageControl)>(epoxy_glDebugMessageControlKHR),
        khr_debug);
}

}  // namespace atrium::gfx
