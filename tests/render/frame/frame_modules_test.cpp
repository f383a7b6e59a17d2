// The frame as modules in stages (render/frame/frame_modules.hpp): the order
// of passes follows the stages modules name, not the order they registered; a
// post-process module replaces the colour image the tone map reads with no
// other edit; the renderer's own passes are modules of their stages; and the
// targets every pass uses are the graph's (the shadow atlas and the light sums
// included), so its listings show them.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "render/frame/frame_modules.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using FrameModulesTest = testing::GlTest;
using testing::kSize;

static_assert(sizeof(render::FrameTargets) == sizeof(glm::ivec2) + sizeof(int),
              "FrameTargets is the targets' shape only: passes reach the GL objects through the graph");

std::vector<std::string> pass_names(World& world) {
  std::vector<std::string> names;
  for (const render::CompiledPass& pass : world.renderer().graph().passes()) {
    if (!pass.culled) names.push_back(pass.name);
  }
  return names;
}

std::ptrdiff_t position(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : it - names.begin();
}

// A module whose one pass keeps itself and does nothing.
render::FrameModule marker(render::FrameStage stage, const std::string& name) {
  return {stage, name, [name](render::FrameBuild& build) {
            build.graph.add_pass(name, [](render::PassBuilder& pass) { pass.keep(); }, [](const render::PassResources&) {});
          }, {}};
}

TEST_F(FrameModulesTest, PassesRunInTheOrderOfTheirStagesNotOfRegistration) {
  World world({.scene = "atrium", .lights = 8u, .mode = "deferred", .size = kSize});
  auto& modules = world.registry().resource<render::FrameModules>();
  modules.add(marker(render::FrameStage::Output, "test output"));
  modules.add(marker(render::FrameStage::PostProcess, "test post"));
  modules.add(marker(render::FrameStage::BeforeLighting, "test before"));
  world.frame(0.0);
  const std::vector<std::string> names = pass_names(world);
  ASSERT_GE(position(names, "test before"), 0);
  EXPECT_LT(position(names, "test before"), position(names, "geometry"));
  EXPECT_GT(position(names, "test post"), position(names, "lighting"));
  EXPECT_LT(position(names, "test post"), position(names, "tonemap"));
  EXPECT_GT(position(names, "test output"), position(names, "tonemap")) << "the renderer's own modules of a stage run first";
}

TEST_F(FrameModulesTest, APostProcessModuleReplacesTheImageTheToneMapReadsWithNoOtherEdit) {
  World world({.scene = "atrium", .lights = 8u, .mode = "clustered-deferred", .size = kSize});
  world.registry().resource<render::FrameModules>().add({render::FrameStage::PostProcess, "test tint", [](render::FrameBuild& build) {
    render::ResourceId tint;
    build.graph.add_pass("test tint", [&](render::PassBuilder& pass) {
      pass.read(build.color, render::Access::Sampled);
      tint = pass.create("test-tint", render::TextureDesc{GL_RGBA16F, build.targets.size, build.targets.samples}, render::ViewKind::Color);
    }, [&graph = build.graph](const render::PassResources& res) {
      const GLfloat red[] = {4.0f, 0.0f, 0.0f, 1.0f};
      glClearTexImage(res.texture(graph.find("test-tint")), 0, GL_RGBA, GL_FLOAT, red);
    });
    build.color = tint;
  }, {}});
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    ASSERT_GT(image.rgba[i], 200) << "pixel " << i / 4;
    ASSERT_EQ(image.rgba[i + 1], 0);
    ASSERT_EQ(image.rgba[i + 2], 0);
  }
  EXPECT_TRUE(world.renderer().offers("test-tint")) << "a post-process image is a debug view by its name";
}

TEST_F(FrameModulesTest, TheRenderersOwnPassesAreModulesOfTheirStages) {
  World world({.scene = "atrium", .lights = 8u, .mode = "forward", .size = kSize});
  std::vector<std::pair<std::string, render::FrameStage>> own;
  for (const render::FrameModule& module : world.renderer().own_modules()) own.emplace_back(module.name, module.stage);
  using S = render::FrameStage;
  EXPECT_EQ(own, (std::vector<std::pair<std::string, S>>{{"occlusion culling", S::BeforeLighting},
                                                          {"shadows", S::BeforeLighting},
                                                          {"counters", S::BeforeLighting},
                                                          {"clear light sums", S::BeforeLighting},
                                                          {"technique", S::Lighting},
                                                          {"tonemap", S::Output},
                                                          {"debug view", S::Output},
                                                          {"present", S::Window}}));
  for (std::size_t i = 1; i < own.size(); ++i) EXPECT_LE(own[i - 1].second, own[i].second) << "listed in stage order";
}

TEST_F(FrameModulesTest, TheShadowAtlasAndTheLightSumsAreTargetsOfTheGraph) {
  WorldOptions options{.scene = "atrium", .lights = 8u, .mode = "tiled-deferred", .size = kSize};
  options.shadows = 2;
  options.technique_options.split_lighting = true;
  World world(options);
  world.frame(0.0);
  std::vector<std::string> viewable;
  for (const render::ViewableResource& resource : world.renderer().graph().viewable()) viewable.push_back(resource.name);
  for (const char* name : {"shadow-atlas", "diffuse-light", "specular-light", "hdr", "depth"}) {
    EXPECT_NE(std::find(viewable.begin(), viewable.end(), name), viewable.end()) << name;
  }
  const std::vector<std::string> names = pass_names(world);
  ASSERT_GE(position(names, "shadows"), 0);
  EXPECT_LT(position(names, "shadows"), position(names, "lighting")) << "the lighting pass reads the atlas the shadows pass draws";
  EXPECT_LT(position(names, "clear light sums"), position(names, "lighting"));
}

}  // namespace
}  // namespace atrium
