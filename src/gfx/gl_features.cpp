#include "gfx/gl_features.hpp"

#include "gfx/allocation_poison.hpp"
#include "gfx/gl.hpp"
#include "gfx/gl_emulation.hpp"

namespace atrium::gfx {
namespace {
GlFeatures g_features;

bool has(const char* extension) { return epoxy_has_gl_extension(extension); }

GlFeatures ask_current_context() {
  GlFeatures f;
  f.es = !epoxy_is_desktop_gl();
  f.version = epoxy_gl_version();
  const int v = f.version;
  if (f.es) {
    // ES is taken at its 3.0 feature set whatever version the driver gives
    // (Mesa answers a 3.0 request with 3.2): the ES path is WebGL2's stand-in
    // on native drivers, and extensions past ES 3.0 are left aside with it.
    f.texture_storage = true;
    f.debug_output = has("GL_KHR_debug");
    f.float_targets = has("GL_EXT_color_buffer_float") && has("GL_EXT_float_blend");
#ifdef __EMSCRIPTEN__
    f.timer_queries = has("GL_EXT_disjoint_timer_query_webgl2");
    f.finish_waits = false;
#endif
    return f;
  }
  f.compute_shaders = v >= 43 || has("GL_ARB_compute_shader");
  f.storage_buffers = v >= 43 || has("GL_ARB_shader_storage_buffer_object");
  f.direct_state_access = v >= 45 || has("GL_ARB_direct_state_access");
  f.buffer_storage = v >= 44 || has("GL_ARB_buffer_storage");
  f.texture_storage = v >= 42 || has("GL_ARB_texture_storage");
  f.multisample_textures = v >= 32;
  f.clip_control = v >= 45 || has("GL_ARB_clip_control");
  f.base_vertex = v >= 32;
  f.multi_draw_indirect = v >= 43 || has("GL_ARB_multi_draw_indirect");
  f.indirect_count = v >= 46 || has("GL_ARB_indirect_parameters");
  f.pipeline_statistics = v >= 46 || has("GL_ARB_pipeline_statistics_query");
  f.binding_qualifiers = v >= 42 || has("GL_ARB_shading_language_420pack");
  f.program_uniforms = v >= 41 || has("GL_ARB_separate_shader_objects");
  f.multi_bind = v >= 44 || has("GL_ARB_multi_bind");
  f.clear_texture = v >= 44 || has("GL_ARB_clear_texture");
  f.read_buffers = f.level_queries = true;
  f.memory_barriers = v >= 42 || has("GL_ARB_shader_image_load_store");
  f.timer_queries = v >= 33 || has("GL_ARB_timer_query");
  f.debug_output = v >= 43 || has("GL_KHR_debug");
  f.framebuffer_limits = v >= 43 || has("GL_ARB_framebuffer_no_attachments");
  f.bindless_textures = has("GL_ARB_bindless_texture");
  f.depth_clamp = f.srgb_write_control = f.float_targets = f.norm16_targets = true;
  return f;
}
}  // namespace

std::string GlFeatures::api_name() const {
  return std::string(es ? "OpenGL ES " : "OpenGL ") + std::to_string(version / 10) + "." + std::to_string(version % 10);
}

std::string GlFeatures::missing_for_full_tier() const {
  std::string missing;
  if (!compute_shaders) missing = "no compute shaders";
  if (!storage_buffers) missing += std::string(missing.empty() ? "" : ", ") + "no storage buffers";
  return missing;
}

const GlFeatures& gl_features() { return g_features; }

void adopt_current_context() {
  g_features = ask_current_context();
  route_missing_entry_points(g_features);
  route_allocation_poison(g_features.direct_state_access);
}

}  // namespace atrium::gfx
