// MSAA in the deferred modes: after the G-buffer pass, GBuffer marks the pixels
// whose samples differ (edges) in the stencil's top bit; a lighting pass then
// runs once per pixel everywhere else and once per sample on the edges, so
// MSAA costs extra shading only where it changes the picture.
// SampleRatePrograms is a lighting pass's program at both rates.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gfx/shader_library.hpp"

namespace atrium::lighting {

// The stencil bit that marks edge pixels; techniques with stencil work of their
// own (light volumes) keep to the bits below it.
inline constexpr GLuint kEdgeStencilBit = 0x80;
inline constexpr GLuint kBelowEdgeBits = kEdgeStencilBit - 1;

class SampleRatePrograms {
 public:
  // The per-sample program is the same files built with PER_SAMPLE, made only
  // when `samples` > 1.
  SampleRatePrograms(gfx::ShaderLibrary& shaders, const std::vector<std::string>& files,
                     std::vector<gfx::ShaderDefine> defines, int samples);

  [[nodiscard]] gfx::ShaderProgram& per_pixel() const { return *pixel_; }
  // nullptr without MSAA.
  [[nodiscard]] gfx::ShaderProgram* per_sample() const { return sample_; }
  // Calls `f` with each program (to set the same uniforms on both).
  void each(const std::function<void(gfx::ShaderProgram&)>& f) const;
  // Calls `draw` with the per-pixel program where the edge bit is clear and
  // with the per-sample program where it is set (the stencil test is left off
  // afterwards); without MSAA once, leaving the stencil alone.
  void draw(const std::function<void(gfx::ShaderProgram&)>& draw) const;

 private:
  gfx::ShaderProgram* pixel_;
  gfx::ShaderProgram* sample_ = nullptr;
};

}  // namespace atrium::lighting
