// An OBJ's material library gives each texture to the material its last
// `newmtl` named. Debian's libassimp 5.2.5 writes through a missing material
// when a texture statement (map_Kd, bump, disp, norm...) comes before any
// `newmtl` (tests/fuzz/regressions/model/assimp-5.2.5-texture-before-newmtl.obj),
// corrupting memory instead of refusing the file. This finds that line first,
// so the library is refused in Atrium's words and never reaches libassimp.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace atrium::assets {

// Empty when no texture statement comes before the first `newmtl` (or there
// is none); otherwise the problem in a few words, naming the line.
[[nodiscard]] std::string mtl_texture_before_material_problem(std::span<const std::uint8_t> bytes);

}  // namespace atrium::assets
