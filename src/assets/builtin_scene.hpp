// The built-in scene "atrium": a procedural courtyard in the spirit of Crytek
// Sponza (two storeys of columns and arches round a paved court, balustrades,
// banners with alpha-masked holes, bronze lamps with emissive glass, a fountain),
// lit by coloured point lights. It needs no files, so the demo and every render
// test run on a machine without the real scenes.
#pragma once

#include <cstdint>
#include <optional>

#include "assets/asset_manager.hpp"
#include "assets/scene.hpp"

namespace atrium::assets {

inline constexpr const char* kBuiltinSceneName = "atrium";
inline constexpr std::uint32_t kBuiltinDefaultLightCount = 160;

// Adds the courtyard's mesh asset and textures to `assets` and returns the scene.
// `light_count` replaces the default number of lights: the lamps' lights come
// first, then seeded coloured lights fill the court.
[[nodiscard]] SceneDescription build_builtin_scene(AssetManager& assets, std::optional<std::uint32_t> light_count = {});

// The lights alone, for a given count (same order and values as the scene's).
[[nodiscard]] std::vector<SceneLight> builtin_scene_lights(std::uint32_t count);

}  // namespace atrium::assets
