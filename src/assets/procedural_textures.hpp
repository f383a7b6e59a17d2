// Procedurally generated material textures for the built-in scene: albedo,
// tangent-space normal (from a height field), glTF metallic-roughness and,
// where the material glows, emissive. All tile seamlessly.
#pragma once

#include <cstdint>
#include <optional>

#include "assets/image.hpp"

namespace atrium::assets {

enum class SurfacePattern : std::uint8_t {
  StoneTiles, Bricks, Marble, Sandstone, WoodPlanks, BannerRed, BannerBlue, BannerGreen, LampGlass, Bronze
};

struct MaterialImages {
  Image albedo;              // sRGB, alpha = coverage (banners cut holes with it)
  Image normal;              // linear, tangent space
  Image metallic_roughness;  // linear, g = roughness, b = metallic
  std::optional<Image> emissive;  // sRGB
};

[[nodiscard]] MaterialImages generate_material_images(SurfacePattern pattern, int size);

}  // namespace atrium::assets
