// The sphere mesh that volume passes draw around each point and spot light:
// light-volumes shades through it, light-prepass accumulates its light buffer
// through it. shaders/common/light_volume.vert places one instance per light.
#pragma once

#include "gfx/gl_object.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::lighting {

class LightSphere {
 public:
  LightSphere();
  // Sets u_circumscribe, the scale that puts the mesh's faces outside the
  // unit sphere, on a program built with common/light_volume.vert.
  void prepare(gfx::ShaderProgram& program) const;
  // Draws `instances` spheres with the program in use (leaves the mesh bound).
  void draw(GLsizei instances = 1) const;

 private:
  gfx::Buffer vertices_;
  gfx::Buffer indices_;
  gfx::VertexArray vertex_array_;
  GLsizei index_count_ = 0;
  float circumscribe_ = 1.0f;
};

}  // namespace atrium::lighting
