#include "render/post/bloom/bloom.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "components/frame_resources.hpp"
#include "components/system_options.hpp"
#include "render/binding_slots.hpp"
#include "render/gpu_assets.hpp"
#include "render/lighting/lighting_pass.hpp"

namespace atrium::render {
namespace {

constexpr char kStrengthOption[] = "bloom";
constexpr char kRadiusOption[] = "bloom-radius";

}  // namespace

int bloom_levels(double radius, int height) {
  const double reach = std::max(radius, 0.0) * static_cast<double>(height) / 3.0;
  int levels = std::clamp(static_cast<int>(std::lround(std::log2(std::max(reach, 1.0)))), 1, kMaxBloomLevels);
  while (levels > 1 && (height >> levels) < 2) --levels;
  return levels;
}

void Bloom::invalidate() { programs_ = {}; }

void Bloom::Programs::fetch(gfx::ShaderLibrary& shaders, bool compute) {
  const char* vertex = "post/fullscreen.vert";
  const auto get = [&](const char* name, std::vector<gfx::ShaderDefine> defines = {}) -> gfx::ShaderProgram* {
    const std::string file = std::string("post/bloom/") + name + (compute ? ".comp" : ".frag");
    return compute ? &shaders.get({file}, defines) : &shaders.get({vertex, file}, defines);
  };
  first_down = get("downsample", {{"FIRST_LEVEL"}});
  down = get("downsample");
  up = get("upsample");
  composite = get("composite");
  this->compute = compute;
}

void Bloom::draw(const PassResources& res, gfx::ShaderProgram& program, ResourceId target, glm::ivec2 size) const {
  if (programs_.compute) {
    glBindImageTexture(kPostImageUnit, res.texture(target), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    lighting::dispatch_per_pixel(program, size);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, res.framebuffer({target}));
  glViewport(0, 0, size.x, size.y);
  program.use();
  triangle_->draw();
}

void Bloom::add_passes(FrameBuild& build) {
  const auto& options = build.registry.resource<SystemOptions>();
  const float strength = static_cast<float>(options.value(kStrengthOption));
  if (strength <= 0.0f) return;
  const glm::ivec2 size = build.targets.size;
  const int levels = bloom_levels(options.value(kRadiusOption, kDefaultBloomRadius), size.y);
  // The passes run where the frame's full-screen passes run (--lighting-stage).
  const bool compute =
      lighting::resolve_lighting_stage(build.registry.resource<RendererSettings>().technique_options) == LightingStage::Compute;
  if (!programs_.first_down || programs_.compute != compute) {
    programs_.fetch(build.registry.resource<GpuAssets>().shaders(), compute);
  }
  if (!triangle_) triangle_ = std::make_unique<FullscreenTriangle>();
  const Access written = compute ? Access::Storage : Access::Attachment;

  // The chain is the module's until the frame's passes have run: their
  // setups fill in the resources that their executions read.
  Chain& c = chain_;
  c = Chain{};
  c.levels = levels;
  c.strength = std::min(strength, 1.0f);
  c.color = build.color;
  c.sizes.push_back(size);
  for (int level = 1; level <= levels; ++level) c.sizes.push_back(glm::max((c.sizes.back() + 1) / 2, glm::ivec2(1)));
  c.down.resize(static_cast<std::size_t>(levels) + 1);
  c.up.resize(static_cast<std::size_t>(levels) + 1);
  build.graph.add_pass("bloom downsample", [&](PassBuilder& pass) {
    pass.read(c.color, Access::Sampled);
    for (int level = 1; level <= levels; ++level) {
      c.down[level] = pass.create("bloom-down-" + std::to_string(level), TextureDesc{GL_RGBA16F, c.sizes[level], 1}, ViewKind::Color);
      pass.write(c.down[level], written);
    }
  }, [this](const PassResources& res) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    for (int level = 1; level <= chain_.levels; ++level) {
      gfx::ShaderProgram& program = level == 1 ? *programs_.first_down : *programs_.down;
      program.set("u_source_size", glm::vec2(chain_.sizes[level - 1]));
      if (programs_.compute) program.set("u_out_size", glm::vec2(chain_.sizes[level]));
      glBindTextureUnit(0, res.texture(level == 1 ? chain_.color : chain_.down[level - 1]));
      draw(res, program, chain_.down[level], chain_.sizes[level]);
      // The next level reads this one: within the pass, so the pass says so.
      if (programs_.compute) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }
  });
  // The smallest level is its own upsampled image.
  c.up[levels] = c.down[levels];
  build.graph.add_pass("bloom upsample", [&](PassBuilder& pass) {
    for (int level = levels; level >= 1; --level) pass.read(c.down[level], Access::Sampled);
    for (int level = levels - 1; level >= 1; --level) {
      c.up[level] = pass.create("bloom-up-" + std::to_string(level), TextureDesc{GL_RGBA16F, c.sizes[level], 1}, ViewKind::Color);
      pass.write(c.up[level], written);
    }
  }, [this](const PassResources& res) {
    gfx::ShaderProgram& program = *programs_.up;
    for (int level = chain_.levels - 1; level >= 1; --level) {
      program.set("u_level_size", glm::vec2(chain_.sizes[level]));
      program.set("u_below_size", glm::vec2(chain_.sizes[level + 1]));
      glBindTextureUnit(0, res.texture(chain_.down[level]));
      glBindTextureUnit(1, res.texture(chain_.up[level + 1]));
      draw(res, program, chain_.up[level], chain_.sizes[level]);
      if (programs_.compute) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }
  });
  build.graph.add_pass("bloom composite", [&](PassBuilder& pass) {
    pass.read(c.color, Access::Sampled);
    pass.read(c.up[1], Access::Sampled);
    c.bloomed = pass.create("bloom-color", TextureDesc{GL_RGBA16F, size, build.targets.samples}, ViewKind::Color);
    pass.write(c.bloomed, written);
  }, [this](const PassResources& res) {
    gfx::ShaderProgram& program = *programs_.composite;
    program.set("u_glow_size", glm::vec2(chain_.sizes[1]));
    program.set("u_size", glm::vec2(chain_.sizes[0]));
    program.set("u_strength", chain_.strength);
    program.set("u_levels", static_cast<float>(chain_.levels));
    glBindTextureUnit(0, res.texture(chain_.color));
    glBindTextureUnit(1, res.texture(chain_.up[1]));
    draw(res, program, chain_.bloomed, chain_.sizes[0]);
  });
  build.color = c.bloomed;
}

void register_bloom(ecs::Registry& registry) {
  auto& options = registry.resource<SystemOptions>();
  options.declare(kStrengthOption, "bloom strength", 0.0, 1.0, SystemOption::Step::Fraction);
  options.declare(kRadiusOption, "bloom radius", 0.02, 1.0, SystemOption::Step::Fraction, kDefaultBloomRadius);
  auto bloom = std::make_shared<Bloom>();
  registry.resource<FrameModules>().add({FrameStage::PostProcess, kStrengthOption, [bloom](FrameBuild& build) { bloom->add_passes(build); },
                                         [bloom] { bloom->invalidate(); }});
}

}  // namespace atrium::render
