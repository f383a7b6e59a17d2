// Light pre-pass (deferred lighting, mode `light-prepass`): a geometry pass
// writes a thin G-buffer (normal, roughness, distance); light volumes add each
// light's BRDF factors into a light buffer that knows no material; a second
// geometry pass reads the materials and the light buffer and writes the lit
// HDR image. The classic answer to a full G-buffer's bandwidth: no albedo,
// metal or emission is stored between passes.
#pragma once

#include <array>

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/light_sphere.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class LightPrepassTechnique final : public LightingTechnique {
 public:
  // The light buffer: the three factors of shaders/common/brdf.glsl's
  // brdf_terms, each summed over lights times their radiance; transient
  // targets of the frame graph named "light-buffer.<target>".
  static constexpr std::array<const char*, 3> kLightBufferTargets{"diffuse", "specular-f0", "specular"};
  static constexpr GLenum kLightBufferFormat = GL_RGBA16F;

  LightPrepassTechnique(render::GpuAssets& gpu, const TechniqueOptions& options);
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

 private:
  void accumulate_lights(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);
  void shade_materials(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets);

  lighting::GBuffer gbuffer_;  // first: the programs below are built with its defines
  lighting::LightSphere sphere_;  // before volumes_, which prepares its programs for it
  gfx::ShaderProgram& geometry_;
  lighting::SampleRatePrograms directional_;
  lighting::VolumePrograms volumes_;
  // With MSAA the material pass runs per sample on the edge pixels too: a
  // fragment there must read the light of its own samples.
  lighting::SampleRatePrograms material_;
  gfx::ShaderProgram& forward_;
  render::FullscreenTriangle fullscreen_;
  std::array<render::ResourceId, kLightBufferTargets.size()> light_buffer_;  // this frame's
};

}  // namespace atrium::techniques
