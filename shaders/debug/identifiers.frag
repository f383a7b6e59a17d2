#version 450 core
// Identifiers as colours (render/debug/debug_views.hpp, show_identifiers): a
// hash of each pixel's value (SHOW_VALUE), or of the draw (SHOW_DRAW: the
// primitive instance) or material (SHOW_MATERIAL) that the visibility
// buffer's triangle identifier names, through its units and the frame's
// instance records. Black where the value is 0 (no geometry). With MSAA
// SHOW_SHARED marks instead, in red over a dark veil, the pixels whose samples
// show two surfaces or more (surface_groups): those the resolve shades more than once.
#include "common/frame.glsl"
// Before the SHOW_SHARED block, whose material.glsl includes it too, for visibility.glsl.
#include "common/material_table.glsl"
#ifdef SHOW_SHARED
// Surfaces are rebuilt, not evaluated: no texture is sampled.
#define EXPLICIT_GRADIENTS
#include "common/material.glsl"
#endif
#include "visibility/visibility.glsl"

layout(location = 0) out vec4 out_color;

// A well-spread colour for any 32-bit value (an integer hash, then its bytes).
vec3 hashed_colour(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return vec3(uvec3(x, x >> 8, x >> 16) & 0xffu) / 255.0 * 0.8 + 0.2;
}

void main() {
#ifdef SHOW_SHARED
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint ids[kSamples], group_of;
  for (int i = 0; i < kSamples; ++i) ids[i] = fetch_sample(u_visibility, pixel, i).r;
  bool shared_pixel = bitCount(surface_groups(pixel, ids, kAnyMaterial, group_of)) > 1;
  out_color = shared_pixel ? vec4(1.0, 0.1, 0.1, 1.0) : vec4(0.0, 0.0, 0.0, 0.6);
#else
  uint id = texelFetch(u_visibility, ivec2(gl_FragCoord.xy), 0).r;
  if (id == 0u) {
    out_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
#if defined(SHOW_DRAW)
  uint value = find_unit(id);
#elif defined(SHOW_MATERIAL)
  uint triangle;
  uint value = visible_instance(id, triangle).material.x;
#else
  uint value = id;
#endif
  out_color = vec4(hashed_colour(value), 1.0);
#endif
}
