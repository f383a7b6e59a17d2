// Shadows for every mode: how much of a light reaches a surface past the
// casters in its shadow maps. The ShadowAtlas (src/render/shadows/) draws the
// maps of this frame's shadowed lights into tiles of one depth texture and
// points each such light's spot.z at its first view; other lights are unshadowed.
// Compiled in only with SHADOWS (the renderer's global define while --shadows
// is above 0): a software rasteriser runs both sides of a branch for a group
// of pixels, so the lookup left in every light loop, even never taken, made
// lighting 2.7x slower on llvmpipe (clustered-deferred, 1024 lights).
#include "frame.glsl"
#include "lights.glsl"

#ifndef SHADOWS
bool has_shadow_maps(Light light) { return false; }
float shadow_visibility(Light light, vec3 position, vec3 normal, vec3 l) { return 1.0; }
#else
// Whether the ShadowAtlas drew maps for `light` this frame.
bool has_shadow_maps(Light light) { return light.spot.z > 0.5; }

// C++ twin: ShadowView in src/render/shadows/shadow_views.hpp.
struct ShadowView {
  mat4 view_projection;  // world to the map's clip space (reversed Z)
  vec4 rect;             // the tile in atlas UV: xy lower-left corner, zw size
  vec4 params;           // x texel width (m, or m per m of distance), y cascade's far view depth, z 1 perspective
};

#ifdef NO_STORAGE_BUFFERS
// The compute-free tier: six RGBA32F texels per view, kShadowViewsPerRow a row
// (C++ twins in src/render/storage_free.hpp).
const uint kShadowViewsPerRow = 341u;  // 2,046 texels
layout(binding = 13) uniform highp sampler2D u_shadow_view_texture;

ShadowView shadow_view_at(uint i) {
  ivec2 first = ivec2(int(i % kShadowViewsPerRow) * 6, int(i / kShadowViewsPerRow));
  mat4 view_projection = mat4(texelFetch(u_shadow_view_texture, first, 0), texelFetch(u_shadow_view_texture, first + ivec2(1, 0), 0),
                              texelFetch(u_shadow_view_texture, first + ivec2(2, 0), 0), texelFetch(u_shadow_view_texture, first + ivec2(3, 0), 0));
  return ShadowView(view_projection, texelFetch(u_shadow_view_texture, first + ivec2(4, 0), 0),
                    texelFetch(u_shadow_view_texture, first + ivec2(5, 0), 0));
}
#else
layout(std430, binding = 9) readonly buffer ShadowViews { ShadowView u_shadow_views[]; };

ShadowView shadow_view_at(uint i) { return u_shadow_views[i]; }
#endif
// Compare mode on: a lookup answers "lit?" for the 2x2 texels around it, blended.
layout(binding = 15) uniform sampler2DShadow u_shadow_atlas;

// How far the looked-up point moves off the surface along its normal, in map
// texels: enough that a texel's depth, tilted away from the light, does not
// shadow the surface it was drawn from (acne), small enough that contact
// shadows stay attached. The slope-scaled depth bias the maps are drawn with
// (kSlopeBias in shadow_atlas.hpp) does the rest.
const float kNormalOffsetTexels = 1.5;

// The view of `light`'s maps that sees `position` (a cube face, the cone, a
// cascade) and the surface's depth along it (for a texel's size); false when
// no map covers it.
bool shadow_view_of(Light light, vec3 position, out uint index, out float depth) {
  index = uint(light.spot.z) - 1u;
  depth = 1.0;
  uint kind = uint(light.color_kind.w);
  if (kind == kLightPoint) {
    // Face order +X, -X, +Y, -Y, +Z, -Z (point_views in shadow_views.cpp).
    vec3 d = position - light.position_radius.xyz;
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) {
      index += d.x >= 0.0 ? 0u : 1u;
      depth = a.x;
    } else if (a.y >= a.z) {
      index += d.y >= 0.0 ? 2u : 3u;
      depth = a.y;
    } else {
      index += d.z >= 0.0 ? 4u : 5u;
      depth = a.z;
    }
  } else if (kind == kLightSpot) {
    depth = dot(position - light.position_radius.xyz, light.direction.xyz);
  } else {
    float view_depth = -(u_view * vec4(position, 1.0)).z;
    uint count = uint(light.spot.w);
    uint cascade = 0u;
    while (cascade < count && view_depth > shadow_view_at(index + cascade).params.y) ++cascade;
    if (cascade == count) return false;
    index += cascade;
  }
  return true;
}

// The share of `light` that reaches `position` (1 lit, 0 shadowed): 3x3
// bilinear comparisons (a 4x4-texel filtered kernel) in the light's map, the
// point moved off the surface along `normal` in proportion to the angle
// between it and `l`, the direction to the light.
float shadow_visibility(Light light, vec3 position, vec3 normal, vec3 l) {
  if (!has_shadow_maps(light)) return 1.0;
  uint index;
  float depth;
  if (!shadow_view_of(light, position, index, depth)) return 1.0;
  ShadowView view = shadow_view_at(index);
  float texel = view.params.x * (view.params.z > 0.5 ? max(depth, 0.0) : 1.0);
  float n_dot_l = clamp(dot(normal, l), 0.0, 1.0);
  vec3 p = position + normal * texel * kNormalOffsetTexels * (0.25 + sqrt(1.0 - n_dot_l * n_dot_l));
  vec4 clip = view.view_projection * vec4(p, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  vec2 step = 1.0 / vec2(textureSize(u_shadow_atlas, 0));
  vec2 lo = view.rect.xy + 0.5 * step, hi = view.rect.xy + view.rect.zw - 0.5 * step;
  vec2 centre = view.rect.xy + uv * view.rect.zw;
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y) {
    for (int x = -1; x <= 1; ++x) lit += textureLod(u_shadow_atlas, vec3(clamp(centre + vec2(x, y) * step, lo, hi), ndc.z), 0.0);
  }
  return lit / 9.0;
}
#endif
