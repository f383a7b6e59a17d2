// The sphere mesh that volume passes draw around each point and spot light:
// light-volumes shades through it, light-prepass accumulates its light buffer
// through it. shaders/common/light_volume.vert places one instance per light.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "render/lighting/sample_rate.hpp"

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

// A volume pass's programs (at both sample rates) twice: built with
// SHADOWED_LIGHTS for the lights that have shadow maps, which lead the light
// buffer, and without for the rest, so that only shadowed lights run the map
// lookup (common/shading.glsl says why that matters).
class VolumePrograms {
 public:
  VolumePrograms(gfx::ShaderLibrary& shaders, const std::vector<std::string>& files, std::vector<gfx::ShaderDefine> defines,
                 int samples, const LightSphere& sphere);
  // The programs for light `index` when the first `shadowed` lights have maps.
  [[nodiscard]] const SampleRatePrograms& of(std::uint32_t index, std::uint32_t shadowed) const {
    return index < shadowed ? shadowed_ : plain_;
  }
  // Calls `f` with every program of both sets.
  void each(const std::function<void(gfx::ShaderProgram&)>& f) const;
  // One instanced draw of `lights` spheres per set (the stencil and blend
  // state are the caller's; the sample rates as SampleRatePrograms::draw).
  void draw_instanced(const LightSphere& sphere, std::uint32_t lights, std::uint32_t shadowed) const;

 private:
  SampleRatePrograms plain_;
  SampleRatePrograms shadowed_;
};

}  // namespace atrium::lighting
