// Reads textures of the frame graph by name, as RGBA floats, from a pass after
// lighting: the way a system that draws reads another pass's resources. For
// tests of transient targets (a G-buffer, the light pre-pass's light buffer),
// which the graph may give to other resources once their last reader has run.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/world.hpp"
#include "render/frame/frame_modules.hpp"

namespace atrium::testing {

// Filled by every frame `world` draws after capture_textures(): single-sample
// textures only, each at its own size, in GL's row order (bottom row first);
// a name the frame's graph lacks is left out.
using Captured = std::map<std::string, std::vector<glm::vec4>>;

// `stage`: the frame stage whose end it reads at (a post-process chain's
// images from the output stage).
inline std::shared_ptr<Captured> capture_textures(World& world, std::vector<std::string> names,
                                                  render::FrameStage stage = render::FrameStage::AfterLighting) {
  auto captured = std::make_shared<Captured>();
  world.registry().resource<render::FrameModules>().add({stage, "test capture",
      [captured, names](render::FrameBuild& build) {
        render::FrameGraph& graph = build.graph;
        graph.add_pass("test capture", [&graph, names](render::PassBuilder& pass) {
          pass.keep();
          for (const std::string& name : names) {
            if (const render::ResourceId id = graph.find(name); id.valid()) pass.read(id, render::Access::Transfer);
          }
        }, [&graph, captured, names](const render::PassResources& res) {
          captured->clear();
          for (const std::string& name : names) {
            const render::ResourceId id = graph.find(name);
            if (!id.valid()) continue;
            std::vector<glm::vec4>& texels = (*captured)[name];
            const glm::ivec2 extent = res.texture_desc(id).size;
            texels.resize(static_cast<std::size_t>(extent.x) * static_cast<std::size_t>(extent.y));
            glGetTextureImage(res.texture(id), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
          }
        }, false);
      }, {}});
  return captured;
}

}  // namespace atrium::testing
