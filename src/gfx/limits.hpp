// What the current GL context allows, asked of the driver, and the error raised
// when a frame would need more: the CLI exits 1 with its message, the window
// undoes the change that caused it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

namespace atrium::gfx {

class ResourceLimitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// GL_MAX_SHADER_STORAGE_BLOCK_SIZE: the most bytes one storage buffer may expose
// to a shader (16 MiB at least; 128 MiB on llvmpipe).
[[nodiscard]] std::uint64_t storage_block_limit();
// GL_MAX_TEXTURE_SIZE: the widest and tallest 2D texture.
[[nodiscard]] int max_texture_size();
// Whether the context can make a 2D texture of `levels` levels of `format` at
// `size`: asked of the proxy target, where a driver refuses what it cannot
// hold (size or memory) without raising an error. True where there is no proxy
// to ask (OpenGL ES and WebGL2, contexts without texture storage).
[[nodiscard]] bool texture_fits(unsigned format, int levels, glm::ivec2 size);
// The largest render size: the smallest of the viewport, framebuffer,
// renderbuffer and texture limits, per axis.
[[nodiscard]] glm::ivec2 max_render_size();

// The most MSAA samples every render target of a frame may have: the smallest of
// GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES, GL_MAX_DEPTH_TEXTURE_SAMPLES and
// GL_MAX_INTEGER_SAMPLES (the compact G-buffer's packed target is integer).
[[nodiscard]] int max_msaa_samples();
// Software rasterisers: Mesa's (llvmpipe, lavapipe, softpipe) and Chromium's
// SwiftShader (WebGL's unmasked renderer, gfx/web_gl.cpp).
[[nodiscard]] bool is_software_renderer();
// The most loop iterations one shader invocation may run, all its loops
// together, or 0 for no limit. llvmpipe silently leaves every loop once a
// shader's SIMD vector has run 65,535 iterations (LP_MAX_TGSI_LOOP_ITERATIONS;
// tests/gfx/limits_test.cpp measures it): a pixel looping over more lights than
// that would drop the rest, so such frames are refused instead.
[[nodiscard]] std::uint32_t shader_loop_limit();

}  // namespace atrium::gfx
