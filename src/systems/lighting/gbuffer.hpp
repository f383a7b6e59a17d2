// The full G-buffer shared by the deferred techniques (reference layout:
// position, albedo, normal, metallic-roughness, emissive) plus the renderer's
// depth-stencil target. Formats are chosen to match forward shading: 32-bit
// float positions, 16-bit unorm normals, 16-bit float emission, sRGB albedo.
#pragma once

#include <array>
#include <span>

#include <glm/glm.hpp>

#include "gfx/gl_object.hpp"
#include "gfx/shader_program.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

class GBuffer {
 public:
  static constexpr std::size_t kTargets = 5;
  struct Target {
    const char* name;
    GLenum format;
    std::size_t bytes_per_pixel;
  };
  static constexpr std::array<Target, kTargets> kLayout{{{"position", GL_RGBA32F, 16},
                                                         {"albedo", GL_SRGB8_ALPHA8, 4},
                                                         {"normal", GL_RGBA16, 8},
                                                         {"metallic-roughness", GL_RGBA8, 4},
                                                         {"emissive", GL_RGBA16F, 8}}};

  // (Re)allocates the colour targets; depth and stencil are the renderer's.
  void resize(glm::ivec2 size, GLuint depth_stencil);

  // Fills the G-buffer with the opaque and masked draw items.
  void draw_geometry(gfx::ShaderProgram& program, const FrameContext& frame);
  // Binds the targets to texture units 0-4 for lighting passes.
  void bind_textures() const;
  // A full-screen pass with `program` reading the G-buffer into the HDR target.
  void draw_fullscreen(gfx::ShaderProgram& program, const FrameTargets& targets) const;

  [[nodiscard]] GLuint texture(std::size_t index) const { return textures_[index].id(); }
  [[nodiscard]] static std::size_t bytes_per_pixel();

 private:
  glm::ivec2 size_{0};
  std::array<gfx::Texture, kTargets> textures_;
  gfx::Framebuffer framebuffer_;
  FullscreenTriangle fullscreen_;
};

}  // namespace atrium::lighting
