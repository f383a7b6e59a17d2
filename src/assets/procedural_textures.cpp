#include "assets/procedural_textures.hpp"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

namespace atrium::assets {
namespace {

std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return h;
}
float hash01(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  return static_cast<float>(hash(x, y, seed) & 0xffffffu) / static_cast<float>(0xffffff);
}

// Value noise on a lattice of `period` cells across [0,1): tiles seamlessly.
float value_noise(glm::vec2 uv, int period, std::uint32_t seed) {
  const glm::vec2 p = uv * static_cast<float>(period);
  const glm::vec2 cell = glm::floor(p);
  const glm::vec2 f = p - cell;
  const glm::vec2 w = f * f * (3.0f - 2.0f * f);
  auto at = [&](int dx, int dy) {
    const int x = (static_cast<int>(cell.x) + dx) % period, y = (static_cast<int>(cell.y) + dy) % period;
    return hash01(static_cast<std::uint32_t>((x + period) % period), static_cast<std::uint32_t>((y + period) % period), seed);
  };
  return glm::mix(glm::mix(at(0, 0), at(1, 0), w.x), glm::mix(at(0, 1), at(1, 1), w.x), w.y);
}

float fbm(glm::vec2 uv, int period, std::uint32_t seed, int octaves = 4) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(uv, period << o, seed + static_cast<std::uint32_t>(o) * 101u);
    total += amplitude;
    amplitude *= 0.5f;
  }
  return sum / total;
}

struct Texel {
  glm::vec3 albedo{0.5f};
  float alpha = 1.0f;
  float height = 0.0f;  // metres-ish, scaled by `bump` when turned into normals
  float roughness = 0.5f;
  float metallic = 0.0f;
  glm::vec3 emissive{0.0f};
};

// Distance from uv to the nearest edge of a cell in a grid of cols x rows.
float edge_distance(glm::vec2 uv, glm::vec2 cells) {
  const glm::vec2 f = glm::fract(uv * cells);
  const glm::vec2 d = glm::min(f, 1.0f - f) / cells;
  return std::min(d.x, d.y);
}

Texel stone_tiles(glm::vec2 uv) {
  Texel t;
  const glm::vec2 cells(4.0f);
  const glm::ivec2 tile(glm::floor(uv * cells));
  const float variation = hash01(static_cast<std::uint32_t>(tile.x), static_cast<std::uint32_t>(tile.y), 7);
  const float grout = glm::smoothstep(0.004f, 0.012f, edge_distance(uv, cells));
  const float n = fbm(uv, 8, 3);
  const glm::vec3 stone = glm::mix(glm::vec3(0.42f, 0.38f, 0.33f), glm::vec3(0.62f, 0.57f, 0.50f), variation) * (0.8f + 0.4f * n);
  t.albedo = glm::mix(glm::vec3(0.16f, 0.15f, 0.14f), stone, grout);
  t.height = grout * (0.6f + 0.4f * n);
  t.roughness = glm::mix(0.95f, 0.55f + 0.3f * n, grout);
  return t;
}

Texel bricks(glm::vec2 uv) {
  Texel t;
  const float rows = 8.0f, cols = 4.0f;
  const float row = std::floor(uv.y * rows);
  glm::vec2 shifted = uv;
  if (static_cast<int>(row) % 2 == 1) shifted.x = std::fmod(shifted.x + 0.5f / cols, 1.0f);
  const glm::ivec2 brick(glm::floor(shifted * glm::vec2(cols, rows)));
  const float variation = hash01(static_cast<std::uint32_t>(brick.x), static_cast<std::uint32_t>(brick.y), 11);
  const float mortar = glm::smoothstep(0.006f, 0.014f, edge_distance(shifted, glm::vec2(cols, rows)));
  const float n = fbm(uv, 16, 5);
  const glm::vec3 clay = glm::mix(glm::vec3(0.45f, 0.20f, 0.12f), glm::vec3(0.66f, 0.38f, 0.24f), variation) * (0.75f + 0.5f * n);
  t.albedo = glm::mix(glm::vec3(0.55f, 0.52f, 0.47f), clay, mortar);
  t.height = mortar * (0.7f + 0.3f * n);
  t.roughness = 0.85f + 0.1f * n;
  return t;
}

Texel marble(glm::vec2 uv) {
  Texel t;
  const float turbulence = fbm(uv, 4, 21, 5);
  const float vein = std::pow(1.0f - std::abs(std::sin((uv.x * 2.0f + uv.y + turbulence * 3.0f) * glm::pi<float>() * 2.0f)), 12.0f);
  t.albedo = glm::mix(glm::vec3(0.86f, 0.84f, 0.80f), glm::vec3(0.35f, 0.36f, 0.40f), vein * 0.8f);
  t.height = 0.2f * turbulence - 0.3f * vein;
  t.roughness = 0.22f + 0.15f * vein;
  return t;
}

Texel sandstone(glm::vec2 uv) {
  Texel t;
  const float n = fbm(uv, 8, 31);
  const float bands = 0.5f + 0.5f * std::sin((uv.y * 6.0f + n * 1.5f) * glm::two_pi<float>());
  t.albedo = glm::mix(glm::vec3(0.62f, 0.50f, 0.34f), glm::vec3(0.78f, 0.66f, 0.46f), bands) * (0.85f + 0.3f * n);
  t.height = 0.5f * n + 0.2f * bands;
  t.roughness = 0.8f;
  return t;
}

Texel wood_planks(glm::vec2 uv) {
  Texel t;
  const float planks = 4.0f;
  const int plank = static_cast<int>(std::floor(uv.y * planks));
  const float variation = hash01(static_cast<std::uint32_t>(plank), 0, 41);
  const float gap = glm::smoothstep(0.004f, 0.01f, std::min(glm::fract(uv.y * planks), 1.0f - glm::fract(uv.y * planks)) / planks);
  const float grain = 0.5f + 0.5f * std::sin((uv.y * 64.0f + fbm(uv + glm::vec2(0, variation), 4, 43) * 6.0f) * glm::two_pi<float>());
  t.albedo = glm::mix(glm::vec3(0.22f, 0.12f, 0.06f), glm::vec3(0.42f, 0.26f, 0.13f), 0.5f * grain + 0.5f * variation) * gap;
  t.height = gap * (0.8f + 0.2f * grain);
  t.roughness = 0.55f + 0.2f * grain;
  return t;
}

Texel banner(glm::vec2 uv, glm::vec3 cloth) {
  Texel t;
  const float weave = 0.5f + 0.25f * (std::sin(uv.x * 256.0f * glm::pi<float>()) + std::sin(uv.y * 256.0f * glm::pi<float>()));
  const glm::vec2 centre = uv - glm::vec2(0.5f, 0.45f);
  // A diamond emblem with a ring, embroidered in gold thread that glows faintly.
  const float diamond = std::abs(centre.x) + std::abs(centre.y);
  const float emblem = (diamond < 0.22f && diamond > 0.17f) || std::abs(glm::length(centre) - 0.08f) < 0.02f ? 1.0f : 0.0f;
  const float border = (uv.x < 0.06f || uv.x > 0.94f || uv.y > 0.95f) ? 1.0f : 0.0f;
  const glm::vec3 gold(0.85f, 0.62f, 0.22f);
  t.albedo = glm::mix(cloth * (0.8f + 0.2f * weave), gold, std::max(emblem, border));
  t.metallic = 0.0f;
  t.roughness = glm::mix(0.9f, 0.45f, emblem);
  t.height = 0.3f * weave + 0.5f * emblem;
  t.emissive = gold * emblem * 0.6f;
  // Holes: a row of round cut-outs and a ragged bottom edge, masked by alpha.
  const glm::vec2 hole_cell = glm::fract(glm::vec2(uv.x * 5.0f, uv.y * 5.0f)) - 0.5f;
  const bool in_hole_band = uv.y > 0.76f && uv.y < 0.92f;
  const float ragged = 0.10f + 0.05f * fbm(glm::vec2(uv.x, 0.0f), 8, 51);
  if ((in_hole_band && glm::length(hole_cell) < 0.22f) || uv.y < ragged) t.alpha = 0.0f;
  return t;
}

Texel lamp_glass(glm::vec2 uv) {
  Texel t;
  const float cage = edge_distance(uv, glm::vec2(8.0f, 4.0f)) < 0.01f ? 1.0f : 0.0f;
  const float flicker = 0.85f + 0.15f * fbm(uv, 4, 61);
  t.albedo = glm::mix(glm::vec3(1.0f, 0.9f, 0.7f), glm::vec3(0.25f, 0.18f, 0.1f), cage);
  t.metallic = cage;
  t.roughness = glm::mix(0.15f, 0.4f, cage);
  t.height = cage;
  t.emissive = glm::vec3(1.0f, 0.78f, 0.45f) * (1.0f - cage) * flicker;
  return t;
}

Texel bronze(glm::vec2 uv) {
  Texel t;
  const float n = fbm(uv, 8, 71, 5);
  const float patina = glm::smoothstep(0.55f, 0.7f, n);
  t.albedo = glm::mix(glm::vec3(0.80f, 0.55f, 0.30f), glm::vec3(0.25f, 0.55f, 0.45f), patina);
  t.metallic = 1.0f - patina;
  t.roughness = glm::mix(0.3f, 0.85f, patina);
  t.height = patina * 0.4f;
  return t;
}

Texel evaluate(SurfacePattern pattern, glm::vec2 uv) {
  switch (pattern) {
    case SurfacePattern::StoneTiles: return stone_tiles(uv);
    case SurfacePattern::Bricks: return bricks(uv);
    case SurfacePattern::Marble: return marble(uv);
    case SurfacePattern::Sandstone: return sandstone(uv);
    case SurfacePattern::WoodPlanks: return wood_planks(uv);
    case SurfacePattern::BannerRed: return banner(uv, glm::vec3(0.55f, 0.06f, 0.05f));
    case SurfacePattern::BannerBlue: return banner(uv, glm::vec3(0.06f, 0.12f, 0.50f));
    case SurfacePattern::BannerGreen: return banner(uv, glm::vec3(0.07f, 0.38f, 0.12f));
    case SurfacePattern::LampGlass: return lamp_glass(uv);
    case SurfacePattern::Bronze: return bronze(uv);
  }
  return {};
}

std::uint8_t to_byte(float v) { return static_cast<std::uint8_t>(std::lround(glm::clamp(v, 0.0f, 1.0f) * 255.0f)); }

float linear_to_srgb(float c) {
  c = glm::clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

Image blank(int size) {
  return Image{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size) * size * 4, 255)};
}

}  // namespace

MaterialImages generate_material_images(SurfacePattern pattern, int size) {
  std::vector<Texel> texels(static_cast<std::size_t>(size) * size);
  bool glows = false;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(size), (static_cast<float>(y) + 0.5f) / static_cast<float>(size));
      Texel& t = texels[static_cast<std::size_t>(y) * size + x];
      t = evaluate(pattern, uv);
      glows = glows || glm::dot(t.emissive, t.emissive) > 0.0f;
    }
  }
  MaterialImages images{blank(size), blank(size), blank(size), std::nullopt};
  if (glows) images.emissive = blank(size);
  const float bump = 2.0f;  // height differences per texel turned into slopes
  auto height_at = [&](int x, int y) {
    return texels[static_cast<std::size_t>((y + size) % size) * size + static_cast<std::size_t>((x + size) % size)].height;
  };
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      const Texel& t = texels[i];
      std::uint8_t* a = &images.albedo.rgba[i * 4];
      for (int c = 0; c < 3; ++c) a[c] = to_byte(linear_to_srgb(t.albedo[c]));
      a[3] = to_byte(t.alpha);
      const glm::vec3 n = glm::normalize(glm::vec3(-(height_at(x + 1, y) - height_at(x - 1, y)) * bump,
                                                   -(height_at(x, y + 1) - height_at(x, y - 1)) * bump, 1.0f));
      std::uint8_t* nm = &images.normal.rgba[i * 4];
      for (int c = 0; c < 3; ++c) nm[c] = to_byte(n[c] * 0.5f + 0.5f);
      std::uint8_t* mr = &images.metallic_roughness.rgba[i * 4];
      mr[0] = 255;
      mr[1] = to_byte(t.roughness);
      mr[2] = to_byte(t.metallic);
      if (images.emissive) {
        std::uint8_t* e = &images.emissive->rgba[i * 4];
        for (int c = 0; c < 3; ++c) e[c] = to_byte(linear_to_srgb(t.emissive[c]));
      }
    }
  }
  return images;
}

}  // namespace atrium::assets
