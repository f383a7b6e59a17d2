#include "render/lighting/light_sums_pass.hpp"

namespace atrium::lighting {

render::FrameModule light_sums_module() {
  return {render::FrameStage::BeforeLighting, "clear light sums", [](render::FrameBuild& build) {
            const render::ResourceId diffuse = build.frame.diffuse_light, specular = build.frame.specular_light;
            if (!diffuse.valid()) return;
            build.graph.add_pass("clear light sums", [&](render::PassBuilder& pass) {
              pass.write(diffuse, render::Access::Transfer);
              pass.write(specular, render::Access::Transfer);
            }, [diffuse, specular](const render::PassResources& res) {
              const GLuint sums = res.framebuffer({diffuse, specular});
              const GLfloat zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
              glClearNamedFramebufferfv(sums, GL_COLOR, 0, zero);
              glClearNamedFramebufferfv(sums, GL_COLOR, 1, zero);
            }, false);
          }, {}};
}

}  // namespace atrium::lighting
