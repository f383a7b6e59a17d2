#include "render/techniques/deferred/deferred.hpp"

#include "render/frame/scene_passes.hpp"

namespace atrium::techniques {

namespace {
std::vector<gfx::ShaderDefine> lighting_defines(bool cull_by_radius) {
  return cull_by_radius ? std::vector<gfx::ShaderDefine>{{"LIGHT_RADIUS_CULL"}} : std::vector<gfx::ShaderDefine>{};
}
}  // namespace

DeferredTechnique::DeferredTechnique(render::GpuAssets& gpu, const TechniqueOptions& options, bool cull_by_radius)
    : shaders_(gpu.shaders()),
      options_(options),
      cull_by_radius_(cull_by_radius),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      lighting_(gpu.shaders(), "deferred/lighting", lighting_defines(cull_by_radius), options),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(gpu.shaders(), options.gbuffer_layout, options.msaa, lighting::lighting_edge_marks(options)) {}

void DeferredTechnique::add_passes(render::FrameGraph& graph, const render::FrameContext& frame, const render::FrameTargets& targets) {
  render::add_geometry_pass(graph, gbuffer_, geometry_, frame, targets);
  graph.add_pass("lighting", [&](render::PassBuilder& pass) {
    lighting_.declare(pass, gbuffer_, frame);
  }, [this, &frame, &targets](const render::PassResources& res) { light(res, frame, targets); });
  render::add_transparency_pass(graph, forward_, frame, targets);
}

void DeferredTechnique::light(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets) {
  const auto lights = static_cast<std::uint32_t>(frame.lights.size());
  const std::uint32_t per_run = lighting::lights_per_run(targets.size, options_.msaa, lighting_.stage());
  std::uint32_t first = 0;
  do {
    const std::uint32_t end = lights - first > per_run ? first + per_run : lights;
    if (first > 0 && !adding_) adding_.emplace(shaders_, "deferred/lighting", lighting_defines(cull_by_radius_), options_, lighting::LightingPass::Write::Add);
    const lighting::LightingPass& pass = first == 0 ? lighting_ : *adding_;
    pass.each([&](gfx::ShaderProgram& program) {
      program.set("u_first_light", first);
      program.set("u_end_light", end);
    });
    pass.run(res, gbuffer_, frame, targets);
    first = end;
  } while (first < lights);
}

}  // namespace atrium::techniques
