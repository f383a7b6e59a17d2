// Light volumes (modes `light-volumes` and `light-volumes-instanced`): after the
// G-buffer, a base pass writes ambient, emission and background; directional
// lights are one full-screen pass; every point and spot light draws a sphere of
// its radius and shades only the pixels inside it, added into the HDR target.
// `light-volumes` finds those pixels exactly with a stencil pass per light
// (z-fail counting, so it works with the camera inside the sphere; depth clamp
// keeps spheres that cross the near or far plane whole). `light-volumes-instanced`
// draws all spheres in one instanced draw of back faces with a GEQUAL depth test
// and no stencil, so the benchmark shows what the stencil pass buys.
#pragma once

#include "render/lighting/gbuffer.hpp"
#include "render/lighting/light_sphere.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {

class LightVolumeTechnique final : public LightingTechnique {
 public:
  LightVolumeTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool instanced);
  void add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) override;

 private:
  void draw_volumes_with_stencil(const render::FrameContext& frame);
  void draw_volumes_instanced(const render::FrameContext& frame);

  bool instanced_;
  gfx::ShaderProgram& geometry_;
  lighting::SampleRatePrograms unlit_;
  lighting::SampleRatePrograms directional_;
  lighting::LightSphere sphere_;
  gfx::ShaderProgram& stencil_;
  lighting::VolumePrograms lighting_;
  gfx::ShaderProgram& forward_;
  lighting::GBuffer gbuffer_;
};

}  // namespace atrium::techniques
