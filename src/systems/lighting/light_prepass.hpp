// Light pre-pass (deferred lighting, mode `light-prepass`): a geometry pass
// writes a thin G-buffer (normal, roughness, distance); light volumes add each
// light's BRDF factors into a light buffer that knows no material; a second
// geometry pass reads the materials and the light buffer and writes the lit
// HDR image. The classic answer to a full G-buffer's bandwidth: no albedo,
// metal or emission is stored between passes.
#pragma once

#include <array>

#include "gfx/gl_object.hpp"
#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/light_sphere.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

class LightPrepassTechnique final : public LightingTechnique {
 public:
  // The light buffer: the three factors of shaders/common/brdf.glsl's
  // brdf_terms, each summed over lights times their radiance.
  static constexpr std::array<const char*, 3> kLightBufferTargets{"diffuse", "specular-f0", "specular"};
  static constexpr GLenum kLightBufferFormat = GL_RGBA16F;

  LightPrepassTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options);
  void resize(const FrameTargets& targets) override;
  void add_passes(render::FrameGraph& graph, const FrameContext& frame, const FrameTargets& targets) override;
  [[nodiscard]] const GBuffer* gbuffer() const override { return &gbuffer_; }
  [[nodiscard]] GLuint light_buffer() const override { return light_buffer_[0].id(); }

  // One of the light buffer's targets, in kLightBufferTargets order (tests read them).
  [[nodiscard]] GLuint light_buffer_target(std::size_t index) const { return light_buffer_[index].id(); }

 private:
  void accumulate_lights(const FrameContext& frame, const FrameTargets& targets);
  void shade_materials(const FrameContext& frame, const FrameTargets& targets);

  GBuffer gbuffer_;  // first: the programs below are built with its defines
  LightSphere sphere_;  // before volumes_, which prepares its programs for it
  gfx::ShaderProgram& geometry_;
  SampleRatePrograms directional_;
  VolumePrograms volumes_;
  // With MSAA the material pass runs per sample on the edge pixels too: a
  // fragment there must read the light of its own samples.
  SampleRatePrograms material_;
  gfx::ShaderProgram& forward_;
  FullscreenTriangle fullscreen_;
  std::array<gfx::Texture, kLightBufferTargets.size()> light_buffer_;
  gfx::Framebuffer light_framebuffer_;
};

}  // namespace atrium::lighting
