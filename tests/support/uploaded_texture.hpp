// The size a World's GPU assets gave a texture's top level: what the upload
// made of it (downscaled, or started at a smaller mip level).
#pragma once

#include <glm/glm.hpp>

#include "app/world.hpp"
#include "gfx/gl.hpp"
#include "render/gpu_assets.hpp"

namespace atrium::testing {

inline glm::ivec2 uploaded_size(World& world, assets::TextureHandle handle = assets::TextureHandle{0}) {
  const GLuint texture = world.registry().resource<render::GpuAssets>().texture(handle);
  glm::ivec2 size{0};
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &size.x);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &size.y);
  return size;
}

}  // namespace atrium::testing
