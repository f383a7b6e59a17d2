// The fireflies' sprites pass: reads the scene depth, adds a camera-facing
// glowing disc per Firefly to the lit HDR image (after lighting, before tone
// mapping), so that each light is seen where it shines from. It owns the GL
// buffer of the sprites and joins the frame as a module of the after-lighting
// stage (render/frame/frame_modules.hpp).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "gfx/shader_program.hpp"
#include "gfx/stream_buffer.hpp"
#include "render/frame/frame_modules.hpp"

namespace atrium {

class FireflySprites {
 public:
  // Adds the "fireflies" pass when the registry holds fireflies.
  void add_pass(render::FrameBuild& build);
  // The module's hook: the program is fetched again (shader globals changed).
  void invalidate() { program_ = nullptr; }

 private:
  // One sprite, the instanced attributes of fireflies/sprite.vert: xyz world
  // position, w radius; then rgb colour.
  struct Sprite {
    glm::vec4 position_size;
    glm::vec4 color;
  };
  void draw(GLuint framebuffer, glm::ivec2 size);

  std::vector<Sprite> sprites_;
  gfx::StreamBuffer buffer_;
  gfx::ShaderProgram* program_ = nullptr;  // from the shader library, on first use
  gfx::VertexArray vertex_array_;  // the sprites as instanced attributes 0 and 1
};

}  // namespace atrium
