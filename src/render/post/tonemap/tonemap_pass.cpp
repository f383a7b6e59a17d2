#include "render/post/tonemap/tonemap_pass.hpp"

#include "components/frame_resources.hpp"
#include "render/lighting/lighting_pass.hpp"

namespace atrium::render {

FrameModule TonemapPass::module() {
  return {FrameStage::Output, "tonemap", [this](FrameBuild& build) {
            const ResourceId color = build.color, output = build.output;
            const bool compute =
                lighting::resolve_lighting_stage(build.registry.resource<RendererSettings>().technique_options) == LightingStage::Compute;
            const glm::ivec2 size = build.targets.size;
            build.graph.add_pass("tonemap", [&](PassBuilder& pass) {
              pass.read(color, Access::Sampled);
              pass.write(output, compute ? Access::Storage : Access::Attachment);
            }, [this, color, output, compute, size](const PassResources& res) {
              glBindTextureUnit(0, res.texture(color));
              if (compute) {
                if (!compute_) compute_ = &shaders_.get({"post/tonemap.comp"});
                glBindImageTexture(kDisplayImageUnit, res.texture(output), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
                lighting::dispatch_per_pixel(*compute_, size);
                return;
              }
              if (!fragment_) fragment_ = &shaders_.get({"post/fullscreen.vert", "post/tonemap.frag"});
              glBindFramebuffer(GL_FRAMEBUFFER, res.framebuffer({output}));
              glViewport(0, 0, size.x, size.y);
              glDisable(GL_DEPTH_TEST);
              glDisable(GL_BLEND);
              glDisable(GL_STENCIL_TEST);
              glDisable(GL_CULL_FACE);
              fragment_->use();
              triangle_.draw();
            });
          }, [this] {
            fragment_ = nullptr;
            compute_ = nullptr;
          }};
}

}  // namespace atrium::render
