#include "render/lighting/sample_rate.hpp"

namespace atrium::lighting {

SampleRatePrograms::SampleRatePrograms(gfx::ShaderLibrary& shaders, const std::vector<std::string>& files,
                                       std::vector<gfx::ShaderDefine> defines, int samples)
    : pixel_(&shaders.get(files, defines)) {
  if (samples <= 1) return;
  defines.push_back({"PER_SAMPLE"});
  sample_ = &shaders.get(files, defines);
}

void SampleRatePrograms::each(const std::function<void(gfx::ShaderProgram&)>& f) const {
  f(*pixel_);
  if (sample_) f(*sample_);
}

void SampleRatePrograms::draw(const std::function<void(gfx::ShaderProgram&)>& draw) const {
  if (!sample_) {
    draw(*pixel_);
    return;
  }
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0);
  glStencilFunc(GL_EQUAL, 0, kEdgeStencilBit);
  draw(*pixel_);
  glStencilFunc(GL_EQUAL, kEdgeStencilBit, kEdgeStencilBit);
  draw(*sample_);
  glStencilMask(0xff);
  glDisable(GL_STENCIL_TEST);
}

}  // namespace atrium::lighting
