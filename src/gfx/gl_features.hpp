// What the current context's OpenGL offers beyond OpenGL ES 3.0 / WebGL2, asked
// once when a context is made (HeadlessContext, WindowContext). The engine is
// written against GL 4.5 core; where a feature is missing, gfx/gl_emulation
// builds its entry points from older calls, shader_program rewrites the GLSL
// dialect, and the renderer runs the compute-free tier (render/storage_free.hpp).
#pragma once

#include <string>

namespace atrium::gfx {

struct GlFeatures {
  bool es = false;   // OpenGL ES (or WebGL2) rather than desktop OpenGL
  int version = 0;   // 45 for 4.5, 30 for ES 3.0
  bool compute_shaders = false;
  bool storage_buffers = false;
  bool direct_state_access = false;  // GL 4.5 / ARB_direct_state_access
  bool buffer_storage = false;       // immutable, persistently mappable buffers (GL 4.4)
  bool texture_storage = false;      // glTexStorage* (GL 4.2, ES 3.0)
  bool multisample_textures = false; // GL 3.2, ES 3.1
  bool clip_control = false;         // glClipControl: clip-space z in [0, 1]
  bool base_vertex = false;          // glDrawElements*BaseVertex (GL 3.2, ES 3.2)
  bool multi_draw_indirect = false;  // GL 4.3
  bool indirect_count = false;       // glMultiDrawElementsIndirectCount (GL 4.6, ARB_indirect_parameters)
  bool pipeline_statistics = false;  // fragment shader invocation queries (GL 4.6, ARB_pipeline_statistics_query)
  bool binding_qualifiers = false;   // GLSL layout(binding = N) (GL 4.2, ES 3.1)
  bool program_uniforms = false;     // glProgramUniform* (GL 4.1, ES 3.1)
  bool multi_bind = false;           // glBindTextures, glBindSamplers (GL 4.4)
  bool clear_texture = false;        // glClearTexImage (GL 4.4)
  bool read_buffers = false;         // glGetBufferSubData (desktop GL)
  bool level_queries = false;        // glGetTexLevelParameteriv (desktop GL, ES 3.1)
  bool memory_barriers = false;      // glMemoryBarrier (GL 4.2, ES 3.1)
  bool timer_queries = false;        // GL_TIME_ELAPSED (GL 3.3; WebGL2 by EXT_disjoint_timer_query_webgl2)
  bool finish_waits = true;          // glFinish returns once the GPU is done (not in browsers,
                                     // where the GPU process runs the commands later)
  bool debug_output = false;         // KHR_debug under its desktop names
  bool framebuffer_limits = false;   // GL_MAX_FRAMEBUFFER_WIDTH (GL 4.3, ES 3.1)
  bool depth_clamp = false;          // GL_DEPTH_CLAMP (GL 3.2)
  bool srgb_write_control = false;   // GL_FRAMEBUFFER_SRGB (desktop; ES always encodes)
  bool norm16_targets = false;       // GL_RGBA16 colour targets (desktop; ES by extension, left aside)
  bool bindless_textures = false;    // ARB_bindless_texture: textures sampled by 64-bit handle
  bool float_targets = false;        // float colour targets, blending included (desktop; ES by
                                     // EXT_color_buffer_float and EXT_float_blend, which WebGL
                                     // turns on when asked about)

  // The compute-free tier is what this context can run.
  [[nodiscard]] bool full_tier() const { return compute_shaders && storage_buffers; }
  // "OpenGL 4.5" or "OpenGL ES 3.0".
  [[nodiscard]] std::string api_name() const;
  // What keeps the full tier off this context: "no compute shaders, no storage
  // buffers"; empty when nothing does.
  [[nodiscard]] std::string missing_for_full_tier() const;
};

// The features of the context made current last (all false before any).
[[nodiscard]] const GlFeatures& gl_features();

// Asks the current context what it offers and routes the entry points it lacks
// to gfx/gl_emulation. Context creation calls it; nothing else needs to.
void adopt_current_context();

}  // namespace atrium::gfx
