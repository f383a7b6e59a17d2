#include "render/output/present_pass.hpp"

#include "components/frame_resources.hpp"

namespace atrium::render {

FrameModule present_module() {
  return {FrameStage::Window, "present", [](FrameBuild& build) {
            if (!build.registry.resource<RendererSettings>().present_to_window) return;
            const ResourceId output = build.output;
            const glm::ivec2 size = build.targets.size;
            build.graph.add_pass("present", [&](PassBuilder& pass) {
              pass.read(output, Access::Transfer);
              pass.keep();
            }, [output, size](const PassResources& res) {
              glBlitNamedFramebuffer(res.framebuffer({output}), 0, 0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            }, false);
          }, {}};
}

}  // namespace atrium::render
