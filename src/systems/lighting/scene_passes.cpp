#include "systems/lighting/scene_passes.hpp"

#include <string>

#include "gfx/depth.hpp"

namespace atrium::lighting {

std::vector<render::ResourceId> add_geometry_pass(render::FrameGraph& graph, GBuffer& gbuffer, gfx::ShaderProgram& program,
                                                  const FrameContext& frame) {
  std::vector<render::ResourceId> targets;
  const auto layout = gbuffer.targets();
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const std::string name = std::string("gbuffer.") + layout[i].name;
    render::ResourceId id = graph.find(name);
    if (!id.valid()) id = graph.import_texture(name, gbuffer.texture(i), {layout[i].format, gbuffer.size(), gbuffer.samples()});
    targets.push_back(id);
  }
  graph.add_pass("geometry", [&](render::PassBuilder& pass) {
    for (const render::ResourceId target : targets) pass.write(target, render::Access::Attachment);
    pass.write(frame.scene_depth, render::Access::Attachment);
  }, [&gbuffer, &program, &frame](const render::PassResources&) { gbuffer.draw_geometry(program, frame); });
  return targets;
}

void read_gbuffer(render::PassBuilder& pass, const std::vector<render::ResourceId>& gbuffer) {
  for (const render::ResourceId target : gbuffer) pass.read(target, render::Access::Sampled);
}

void add_transparency_pass(render::FrameGraph& graph, gfx::ShaderProgram& program, const FrameContext& frame, const FrameTargets& targets,
                           const std::function<void(render::PassBuilder&)>& reads, std::function<void()> prepare) {
  if (frame.draws.blended.empty()) return;
  graph.add_pass("transparency", [&](render::PassBuilder& pass) {
    pass.read(frame.scene_depth, render::Access::Attachment);
    pass.read(frame.light_buffer, render::Access::Storage);
    if (reads) reads(pass);
    pass.write(frame.scene_color, render::Access::Attachment);
  }, [&program, &frame, &targets, prepare = std::move(prepare)](const render::PassResources&) {
    if (prepare) prepare();
    draw_transparent(program, frame, targets);
  });
}

}  // namespace atrium::lighting
