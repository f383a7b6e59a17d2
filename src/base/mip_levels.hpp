// The levels of a texture's full mip chain, as OpenGL counts them: each level
// halves the one before (rounding down) until both sides are 1. One count for
// what the DDS reader accepts, what textures allocate and what tests ask.
#pragma once

#include <algorithm>
#include <bit>

namespace atrium {

[[nodiscard]] constexpr int mip_levels(int width, int height) {
  return std::bit_width(static_cast<unsigned>(std::max({width, height, 1})));
}

static_assert(mip_levels(1, 1) == 1 && mip_levels(3, 1) == 2 && mip_levels(16384, 16) == 15 && mip_levels(0, -4) == 1);

}  // namespace atrium
