// What the camera sees of an entity, per primitive and per meshlet: the frustum
// culling system (systems/frustum_culling.hpp) marks what lies in the view, and
// occlusion culling (render/culling/occlusion_culling.hpp) what the depth buffer hides.
// Every pass that draws scene geometry reads it through the frame's draw list.
#pragma once

#include <cstdint>
#include <vector>

namespace atrium {

// Bits of a primitive's or a meshlet's visibility state.
namespace seen {
// In the view frustum and not facing away (frustum culling, each frame).
inline constexpr std::uint8_t kInView = 1u << 0;
// Shown in the last frame's depth: the first pass draws it before testing the
// rest (occlusion culling; kept across frames while in view).
inline constexpr std::uint8_t kLastFrame = 1u << 1;
// Not shown last frame, but this frame's first depth does not hide it: drawn
// late in the first pass and in every pass after it (occlusion culling).
inline constexpr std::uint8_t kRevealed = 1u << 2;
// This frame's first depth hides it: the next frame does not draw it first
// (occlusion culling; cleared each frame with kRevealed).
inline constexpr std::uint8_t kHidden = 1u << 3;
}  // namespace seen

struct Visibility {
  bool any = true;  // some primitive of the entity is in view
  // seen:: bits per primitive of the entity's mesh, in the mesh's order; empty
  // means all in view and shown. A primitive cut into meshlets is in view when
  // one of them is, and draws the meshlets that are.
  std::vector<std::uint8_t> primitives;
  // seen:: bits per meshlet, in WorldBounds::meshlets's order.
  std::vector<std::uint8_t> meshlets;
};

// The culling systems' counts of the last frame, for stats and tests.
struct CullingStats {
  std::size_t objects = 0;             // entities with a mesh
  std::size_t objects_visible = 0;
  std::size_t primitives = 0;          // primitive instances
  std::size_t primitives_visible = 0;
  std::size_t meshlets = 0;            // of the primitive instances in the frustum
  std::size_t meshlets_visible = 0;    // in the frustum and not facing away
};

}  // namespace atrium
