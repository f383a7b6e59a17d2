#include "render/lighting/lighting_pass.hpp"

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
      if (options.msaa > 1) {
        throw gfx::ResourceLimitError("--lighting-stage compute with --msaa " + std::to_string(options.msaa) +
                                      ": the compute stage does not shade MSAA edges per sample; use --lighting-stage fragment or auto "
                                      "with MSAA");
      }
      return LightingStage::Compute;
    case LightingStage::Automatic: break;
  }
  if (options.compute_free || options.msaa > 1 || gfx::is_software_renderer()) return LightingStage::Fragment;
  return LightingStage::Compute;
}

std::string_view lighting_stage_name(LightingStage stage) { return kLightingStageNames[static_cast<std::size_t>(stage)]; }

void dispatch_per_pixel(gfx::ShaderProgram& program, glm::ivec2 size) {
  GLint group[3] = {1, 1, 1};
  glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, group);
  program.use();
  glDispatchCompute(static_cast<GLuint>((size.x + group[0] - 1) / group[0]), static_cast<GLuint>((size.y + group[1] - 1) / group[1]), 1);
}

LightingPass::LightingPass(gfx::ShaderLibrary& shaders, const std::string& file, std::vector<gfx::ShaderDefine> defines,
                           const TechniqueOptions& options) {
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

void LightingPass::declare(render::PassBuilder& pass, const GBuffer& gbuffer, const FrameContext& frame) const {
  gbuffer.read_targets(pass);
  const render::Access access = compute_ ? render::Access::Storage : render::Access::Attachment;
  pass.write(frame.scene_color, access);
  for (const render::ResourceId sum : {frame.diffuse_light, frame.specular_light}) {
    if (sum.valid()) pass.write(sum, access);
  }
}

void LightingPass::run(const render::PassResources& res, const GBuffer& gbuffer, const FrameContext& frame, const FrameTargets& targets) const {
  if (!compute_) {
    gbuffer.draw_fullscreen(res, *fragment_, targets);
    return;
  }
  gbuffer.bind_textures(res);
  glBindImageTexture(kLitColorImageUnit, res.texture(frame.scene_color), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  if (frame.diffuse_light.valid()) {
    glBindImageTexture(kDiffuseLightImageUnit, res.texture(frame.diffuse_light), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(kSpecularLightImageUnit, res.texture(frame.specular_light), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  }
  dispatch_per_pixel(*compute_, targets.size);
}

}  // namespace atrium::lighting
