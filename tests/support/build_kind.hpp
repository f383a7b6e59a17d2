// What the asset tests expect differently of the browser build, which runs
// them under Node too (web/CMakeLists.txt, ctest web.asset_tests): it has no
// libassimp, libmeshoptimizer or libdraco (assets/web/ refuses what needs them,
// in one line), and its size_t is 32 bits. Everything else must behave alike,
// messages included.
#pragma once

#include <cstddef>

namespace atrium::testing {

#ifdef __EMSCRIPTEN__
inline constexpr bool kBrowserBuild = true;
#else
inline constexpr bool kBrowserBuild = false;
#endif
inline constexpr bool k32BitSizes = sizeof(std::size_t) < 8;

}  // namespace atrium::testing
