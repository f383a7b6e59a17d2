// Bloom (post-process stage): the glow that bright lights spread over their
// surroundings, as a camera's lens and an eye spread it. Reads the frame's
// colour image (FrameBuild::color), halves it level by level into
// "bloom-down-1".."bloom-down-N" (Jimenez's 13-tap filter, Karis's average on
// the first), adds each level to the tent-filtered one below it on the way up
// ("bloom-up-N-1".."bloom-up-1"), and writes "bloom-color", the colour image
// moved towards that glow by the strength; that image is the new colour handle.
// Fragment passes, or compute passes with the compute lighting stage. Off
// (no pass) at strength 0. Its options: "bloom" (--bloom S, the strength)
// and "bloom-radius" (--bloom-radius R, how far the glow reaches as a fraction
// of the image height), a scene file's "systems" object and the overlay.
#pragma once

#include <memory>
#include <vector>

#include "ecs/registry.hpp"
#include "gfx/shader_library.hpp"
#include "render/frame/draw_list.hpp"
#include "render/frame/frame_modules.hpp"

namespace atrium::render {

inline constexpr double kDefaultBloomRadius = 0.2;
inline constexpr int kMaxBloomLevels = 8;

// Levels of the chain for a glow reaching `radius` of an image `height`
// pixels tall: the widest level's 3x3 tent spans about that far. At least one,
// and never a level under two pixels high.
[[nodiscard]] int bloom_levels(double radius, int height);

class Bloom {
 public:
  void add_passes(FrameBuild& build);
  // The module's hook: programs are fetched again.
  void invalidate();

 private:
  // This frame's chain: level 0 is the colour image.
  struct Chain {
    int levels = 0;
    float strength = 0.0f;
    std::vector<glm::ivec2> sizes;
    std::vector<ResourceId> down, up;  // per level; up[levels] is down[levels]
    ResourceId color, bloomed;
  };
  Chain chain_;
  // Fragment programs, or with the compute lighting stage compute programs
  // that store with imageStore; fetched on first use and after invalidate().
  struct Programs {
    gfx::ShaderProgram* first_down = nullptr;
    gfx::ShaderProgram* down = nullptr;
    gfx::ShaderProgram* up = nullptr;
    gfx::ShaderProgram* composite = nullptr;
    bool compute = false;
    void fetch(gfx::ShaderLibrary& shaders, bool compute);
  };
  Programs programs_;
  std::unique_ptr<FullscreenTriangle> triangle_;
  // Draws `program` over `target` (a full-screen triangle, or a dispatch per texel).
  void draw(const PassResources& res, gfx::ShaderProgram& program, ResourceId target, glm::ivec2 size) const;
};

// Declares the options and adds the "bloom" module to the frame's
// post-process stage. The registry must hold SystemOptions, GpuAssets and
// render::FrameModules.
void register_bloom(ecs::Registry& registry);

}  // namespace atrium::render
