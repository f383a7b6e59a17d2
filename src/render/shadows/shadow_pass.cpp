#include "render/shadows/shadow_pass.hpp"

namespace atrium::shadows {

render::FrameModule shadow_module(ShadowAtlas& atlas, render::FrameDraws& draws) {
  return {render::FrameStage::BeforeLighting, "shadows", [&atlas, &draws](render::FrameBuild& build) {
            if (!atlas.has_pending() || !build.frame.shadow_atlas.valid()) return;
            // The maps not drawn again stay: the pass keeps (reads) the atlas it draws into.
            build.graph.add_pass("shadows", [&](render::PassBuilder& pass) {
                                   pass.read(build.frame.shadow_atlas, render::Access::Attachment);
                                   pass.write(build.frame.shadow_atlas, render::Access::Attachment);
                                 },
                                 [&atlas, &draws, &registry = build.registry](const render::PassResources&) {
                                   atlas.draw_pending(registry);
                                   draws.bind();  // the shadow passes bound casters of their own
                                 });
          }, {}};
}

}  // namespace atrium::shadows
