#version 450 core
// Tiled light culling, second step, one of two ways (LightIndexList picks per
// frame). Scatter (common/light_scatter.glsl): each light visits only the
// tiles under its sphere's screen rectangle and passes those whose frustum and
// depth bounds (tile_bounds.comp) it touches, so the cost follows the tiles
// each light covers rather than every light for every tile. GATHER
// (common/light_gather.glsl): each tile tests every light with the same test.
#include "common/light_assignment.glsl"
#ifdef GATHER
#include "common/light_gather.glsl"
#else
#include "common/light_scatter.glsl"
#endif
#include "tiled/tiles.glsl"

bool touches(vec4 sphere, TileBounds tile) {
  if (tile.depths.z > 0.5) return false;
  if (sphere.w < 0.0) return true;
  if (-sphere.z + sphere.w < tile.depths.x || -sphere.z - sphere.w > tile.depths.y) return false;
  for (int p = 0; p < 4; ++p) {
    if (dot(tile.planes[p].xyz, sphere.xyz) < -sphere.w) return false;
  }
  return true;
}

#ifdef GATHER
TileBounds g_tile;

// The box around the tile's frustum between its depths: its corner rays (where
// neighbouring side planes meet, scaled to depth 1) at both depths.
bool gather_bin(uint bin, out vec3 lo, out vec3 hi) {
  g_tile = u_tile_bounds[bin];
  lo = vec3(1e30);
  hi = vec3(-1e30);
  if (g_tile.depths.z > 0.5) return false;
  for (int corner = 0; corner < 4; ++corner) {
    vec3 ray = cross(g_tile.planes[(corner + 3) % 4].xyz, g_tile.planes[corner].xyz);
    ray /= -ray.z;
    for (int end = 0; end < 2; ++end) {
      vec3 point = ray * g_tile.depths[end];
      lo = min(lo, point);
      hi = max(hi, point);
    }
  }
  return true;
}

bool gather_touches(vec4 sphere) { return touches(sphere, g_tile); }
#else
// The tiles under the screen rectangle of the sphere's view-space box (one
// tile more on each side, for rounding), or every tile when the box reaches
// the eye's plane, where projection no longer bounds it; false for a sphere
// wholly behind the eye, which no tile's depth bounds (never negative) admit.
bool tile_rect(vec4 sphere, out uvec2 lo, out uvec2 hi) {
  lo = uvec2(0u);
  hi = u_tiles - 1u;
  if (sphere.w >= 0.0 && sphere.z - sphere.w > 0.0) return false;
  if (sphere.w < 0.0 || !(sphere.z + sphere.w < -1e-4)) return true;
  vec2 ndc_lo = vec2(1e30), ndc_hi = vec2(-1e30);
  for (int corner = 0; corner < 8; ++corner) {
    vec3 offset = vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, (corner & 4) != 0 ? 1.0 : -1.0);
    vec4 clip = u_projection * vec4(sphere.xyz + offset * sphere.w, 1.0);
    vec2 ndc = clip.xy / clip.w;
    ndc_lo = min(ndc_lo, ndc);
    ndc_hi = max(ndc_hi, ndc);
  }
  if (any(isnan(ndc_lo)) || any(isnan(ndc_hi))) return true;
  vec2 tiles = vec2(u_tiles);
  vec2 first = clamp(floor((ndc_lo * 0.5 + 0.5) * u_viewport_size / 16.0) - 1.0, vec2(0.0), tiles - 1.0);
  vec2 last = clamp(floor((ndc_hi * 0.5 + 0.5) * u_viewport_size / 16.0) + 1.0, vec2(0.0), tiles - 1.0);
  lo = uvec2(first);
  hi = uvec2(last);
  return true;
}

// The candidates are the rectangle's tiles, numbered row by row.
uint candidate_count(vec4 sphere) {
  uvec2 lo, hi;
  if (!tile_rect(sphere, lo, hi)) return 0u;
  return (hi.x - lo.x + 1u) * (hi.y - lo.y + 1u);
}

uint for_each_bin(vec4 sphere, uint first, uint stride) {
  uvec2 lo, hi;
  if (!tile_rect(sphere, lo, hi)) return 0u;
  uint width = hi.x - lo.x + 1u, count = width * (hi.y - lo.y + 1u);
  uint visited = 0u;
  for (uint c = first; c < count; c += stride) {
    uint tile = (lo.y + c / width) * u_tiles.x + lo.x + c % width;
    if (!touches(sphere, u_tile_bounds[tile])) continue;
    visit_bin(tile);
    ++visited;
  }
  return visited;
}
#endif
