// What the GPU's copy of the light buffer holds (the tests that check what
// the LightBuffer sent, what a later system patched, and what the GPU moved).
#pragma once

#include <vector>

#include "gfx/gl.hpp"
#include "render/light_buffer.hpp"

namespace atrium::testing {

inline std::vector<render::GpuLight> read_back_lights(const render::LightBuffer& buffer) {
  std::vector<render::GpuLight> lights(buffer.count);
  glGetNamedBufferSubData(buffer.buffer.id(), 0, static_cast<GLsizeiptr>(lights.size() * sizeof(render::GpuLight)), lights.data());
  return lights;
}

}  // namespace atrium::testing
