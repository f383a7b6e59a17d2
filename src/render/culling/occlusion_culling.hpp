// Two-phase occlusion culling, run inside each technique's first pass over
// opaque geometry (the one that fills the depth buffer): the pass draws what
// the last frame showed, the depth it wrote is read back as a pyramid of
// farthest depths, everything in view is tested against it, what it does not
// hide and was not drawn is drawn too (seen::kRevealed), and what it does not
// hide is what the next frame draws first (seen::kLastFrame). One pyramid a
// frame, as in Niagara: the completed depth would drop, a frame sooner, what
// only the revealed surfaces hide, for a second read of the depth. Only after
// a camera cut, when the first depth is mostly what the last view chose, is
// the completed depth read again to choose. A
// surface is left out only where drawn depth lies in front of all of it, so
// every mode still draws the picture it draws without culling; what the test
// saves is the vertex work of hidden geometry (a street of the Bistro-scale
// grid hides nine tenths of what is in view).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "components/frame_resources.hpp"
#include "ecs/registry.hpp"
#include "gfx/gl.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"

namespace atrium::render {

// The depth buffer's farthest view depth per kTileSize-pixel tile, and coarser
// levels above it (each texel the farthest of the four below): what a box
// must lie behind everywhere to be hidden.
class DepthPyramid {
 public:
  static constexpr int kTileSize = 8;  // pixels per tile side (culling/depth_tiles.comp's work group)

  DepthPyramid() = default;
  // `tiles`: farthest view depth (metres; infinity where nothing was drawn) of
  // each tile, rows from the bottom of the viewport up (GL's order).
  DepthPyramid(std::vector<float> tiles, glm::ivec2 tile_count, glm::ivec2 viewport);

  // Whether the world-space box lies behind the depth over every pixel it
  // covers, seen through `view` and `projection` (a perspective one). False
  // for a box that reaches the near plane, and for an empty pyramid.
  [[nodiscard]] bool hides(const glm::mat4& view, const glm::mat4& projection, float near_plane, glm::vec3 min,
                           glm::vec3 max) const;

  [[nodiscard]] bool empty() const { return levels_.empty(); }

 private:
  struct Level {
    glm::ivec2 size{0};
    std::vector<float> farthest;
  };
  std::vector<Level> levels_;
  glm::ivec2 viewport_{0};
};

// Tests every opaque primitive and meshlet in view against `depth` (the
// first phase's): sets seen::kHidden on those it hides, and seen::kRevealed
// on the others that the last frame did not show. Returns how many it revealed.
std::size_t reveal_unhidden(ecs::Registry& registry, const DepthPyramid& depth, const ViewState& view);
// Once this frame's lists are built: sets seen::kLastFrame, for the next
// frame, on every opaque primitive and meshlet in view that reveal_unhidden()
// did not hide and clears it on those it hid (frustum culling clears it on
// what leaves the view). On a camera cut (ViewState::cut), `full_depth`, the
// depth after every draw, chooses instead: the first depth came from the last
// view's choice and hides little. Returns the triangles in view that no pass draws.
std::size_t remember_shown(ecs::Registry& registry, const ViewState& view, const DepthPyramid* full_depth = nullptr);

// Writes the farthest view depth of each 8x8-pixel tile of `depth` (`tiles`
// of them, rows from the bottom) to the start of `buffer`
// (culling/depth_tiles.comp): the pyramid's finest level, for the CPU and the
// GPU path alike. The frame uniforms must be bound; the program it uses stays in use.
void write_depth_tiles(gfx::ShaderLibrary& shaders, GLuint depth, glm::ivec2 tiles, GLuint buffer);

// Reads a depth buffer back as a DepthPyramid (culling/depth_tiles.comp).
class DepthReader {
 public:
  explicit DepthReader(gfx::ShaderLibrary& shaders) : shaders_(shaders) {}
  // `depth`: the frame's depth-stencil texture (multisampled when the global
  // MSAA_SAMPLES define says so); the frame uniforms must be bound. Keeps the
  // program in use and frees the texture unit it borrows.
  [[nodiscard]] DepthPyramid read(GLuint depth, glm::ivec2 size);

 private:
  gfx::ShaderLibrary& shaders_;
  gfx::Buffer tiles_;
  std::size_t capacity_ = 0;  // floats
};

}  // namespace atrium::render
