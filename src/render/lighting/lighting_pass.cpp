#include "render/lighting/lighting_pass.hpp"

#include <algorithm>
#include <array>

#include "gfx/limits.hpp"

namespace atrium::lighting {

LightingStage resolve_lighting_stage(const TechniqueOptions& options) {
  switch (options.lighting_stage) {
    case LightingStage::Fragment: return LightingStage::Fragment;
    case LightingStage::Compute:
      if (options.compute_free) {
        throw gfx::ResourceLimitError("--lighting-stage compute needs compute shaders and storage images, which the compute-free "
                                      "tier does not use; use --lighting-stage fragment or auto there");
      }
      return LightingStage::Compute;
    case LightingStage::Automatic: break;
  }
  if (options.compute_free || gfx::is_software_renderer()) return LightingStage::Fragment;
  return LightingStage::Compute;
}

GBuffer::EdgeMarks lighting_edge_marks(const TechniqueOptions& options) {
  return resolve_lighting_stage(options) == LightingStage::Compute ? GBuffer::EdgeMarks::None : GBuffer::EdgeMarks::Stencil;
}

std::string_view lighting_stage_name(LightingStage stage) { return kLightingStageNames[static_cast<std::size_t>(stage)]; }

void dispatch_per_pixel(gfx::ShaderProgram& program, glm::ivec2 size) {
  const glm::uvec2 group(program.work_group_size());
  const glm::uvec2 pixels(glm::max(size, glm::ivec2(0)));
  program.use();
  glDispatchCompute((pixels.x + group.x - 1) / group.x, (pixels.y + group.y - 1) / group.y, 1);
}

std::uint32_t lights_per_run(glm::ivec2 size, int msaa, LightingStage stage) {
  const std::uint64_t budget = stage == LightingStage::Compute ? kComputeEvaluationsPerRun : kFragmentEvaluationsPerRun;
  const glm::u64vec2 pixels(glm::max(size, glm::ivec2(0)));
  const std::uint64_t samples = pixels.x * pixels.y * static_cast<std::uint64_t>(std::max(msaa, 1));
  return static_cast<std::uint32_t>(std::clamp<std::uint64_t>(budget / std::max<std::uint64_t>(samples, 1), 1, kMostLightsPerRun));
}

void bind_lit_images(const render::PassResources& res, const render::FrameContext& frame, GLenum access) {
  glBindImageTexture(render::kLitColorImageUnit, res.texture(frame.scene_color), 0, GL_FALSE, 0, access, GL_RGBA16F);
  if (frame.diffuse_light.valid()) {
    glBindImageTexture(render::kDiffuseLightImageUnit, res.texture(frame.diffuse_light), 0, GL_FALSE, 0, access, GL_RGBA16F);
    glBindImageTexture(render::kSpecularLightImageUnit, res.texture(frame.specular_light), 0, GL_FALSE, 0, access, GL_RGBA16F);
  }
}

LightingPass::LightingPass(gfx::ShaderLibrary& shaders, const std::string& file, std::vector<gfx::ShaderDefine> defines,
                           const TechniqueOptions& options, Write write)
    : write_(write) {
  if (write == Write::Add) defines.push_back({"ADD_LIGHTS"});
  if (resolve_lighting_stage(options) == LightingStage::Compute) {
    compute_ = &shaders.get({file + ".comp"}, defines);
  } else {
    fragment_.emplace(shaders, std::vector<std::string>{"post/fullscreen.vert", file + ".frag"}, std::move(defines), options.msaa);
  }
}

void LightingPass::each(const std::function<void(gfx::ShaderProgram&)>& f) const {
  if (compute_) f(*compute_);
  else fragment_->each(f);
}

void LightingPass::declare(render::PassBuilder& pass, const GBuffer& gbuffer, const render::FrameContext& frame) const {
  gbuffer.read_targets(pass);
  render::read_shading_inputs(pass, frame);
  const render::Access access = compute_ ? render::Access::Storage : render::Access::Attachment;
  pass.write(frame.scene_color, access);
  for (const render::ResourceId sum : {frame.diffuse_light, frame.specular_light}) {
    if (sum.valid()) pass.write(sum, access);
  }
}

void LightingPass::run(const render::PassResources& res, const GBuffer& gbuffer, const render::FrameContext& frame, const render::FrameTargets& targets) const {
  const bool add = write_ == Write::Add;
  if (!compute_) {
    if (add) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_ONE, GL_ONE);
    }
    gbuffer.draw_fullscreen(res, *fragment_, frame, targets);
    if (add) glDisable(GL_BLEND);
    return;
  }
  gbuffer.bind_textures(res);
  bind_lit_images(res, frame, add ? GL_READ_WRITE : GL_WRITE_ONLY);
  // The run before stored these pixels: its stores must land before this run reads them.
  if (add) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  dispatch_per_pixel(*compute_, targets.size);
}

}  // namespace atrium::lighting
