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
#include "render/contributors.hpp"

namespace atrium::testing {

// Filled by every frame `world` draws after capture_textures(): single-sample
// textures only, in GL's row order (bottom row first); a name the frame's
// graph lacks is left out.
using Captured = std::map<std::string, std::vector<glm::vec4>>;

inline std::shared_ptr<Captured> capture_textures(World& world, std::vector<std::string> names) {
  auto captured = std::make_shared<Captured>();
  world.registry().resource<RenderContributors>().after_lighting.push_back(
      [captured, names](render::FrameGraph& graph, ecs::Registry&, const lighting::FrameContext&, const lighting::FrameTargets& targets) {
        graph.add_pass("test capture", [&graph, names](render::PassBuilder& pass) {
          pass.keep();
          for (const std::string& name : names) {
            if (const render::ResourceId id = graph.find(name); id.valid()) pass.read(id, render::Access::Transfer);
          }
        }, [&graph, captured, names, size = targets.size](const render::PassResources& res) {
          captured->clear();
          for (const std::string& name : names) {
            const render::ResourceId id = graph.find(name);
            if (!id.valid()) continue;
            std::vector<glm::vec4>& texels = (*captured)[name];
            texels.resize(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
            glGetTextureImage(res.texture(id), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)), texels.data());
          }
        }, false);
      });
  return captured;
}

}  // namespace atrium::testing
