#include "systems/fireflies/firefly_sprites.hpp"

#include "render/gpu_assets.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "gfx/depth.hpp"
#include "systems/fireflies/firefly.hpp"

namespace atrium {
namespace {

// The attribute locations of shaders/fireflies/sprite.vert.
constexpr GLuint kPositionSizeLocation = 0, kColorLocation = 1;

}  // namespace

void FireflySprites::add_pass(render::FrameBuild& build) {
  ecs::Registry& registry = build.registry;
  sprites_.clear();
  registry.view<Firefly, Transform, LightColor>().each([&](ecs::Entity, const Firefly& firefly, const Transform& transform, const LightColor& light) {
    sprites_.push_back({glm::vec4(transform.position, firefly.size), glm::vec4(light.color, 0.0f)});
  });
  if (sprites_.empty()) return;
  if (!program_) {
    program_ = &registry.resource<render::GpuAssets>().shaders().get({"fireflies/sprite.vert", "fireflies/sprite.frag"});
    vertex_array_ = gfx::create_vertex_array();
    const GLuint vao = vertex_array_.id();
    for (const GLuint location : {kPositionSizeLocation, kColorLocation}) {
      glEnableVertexArrayAttrib(vao, location);
      glVertexArrayAttribFormat(vao, location, 4, GL_FLOAT, GL_FALSE, location == kColorLocation ? sizeof(glm::vec4) : 0);
      glVertexArrayAttribBinding(vao, location, 0);
    }
    glVertexArrayBindingDivisor(vao, 0, 1);
  }
  const render::ResourceId color = build.frame.scene_color, depth = build.frame.scene_depth;
  build.graph.add_pass("fireflies", [&](render::PassBuilder& pass) {
    pass.read(depth, render::Access::Attachment);
    pass.write(color, render::Access::Attachment);
  }, [this, color, depth, size = build.targets.size](const render::PassResources& res) { draw(res.framebuffer({color}, depth), size); });
}

void FireflySprites::draw(GLuint framebuffer, glm::ivec2 size) {
  buffer_.upload(sprites_.data(), sprites_.size() * sizeof(Sprite));
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, size.x, size.y);
  // Hidden behind the scene where it is, glowing over it where it is not.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  program_->use();
  // The buffer is remade when it grows: bound to the vertex array each frame.
  glVertexArrayVertexBuffer(vertex_array_.id(), 0, buffer_.buffer.id(), 0, sizeof(Sprite));
  glBindVertexArray(vertex_array_.id());
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(sprites_.size()));
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glEnable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
}

}  // namespace atrium
