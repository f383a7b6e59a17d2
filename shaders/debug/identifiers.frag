#version 450 core
// Identifiers as colours (render/debug/debug_views.hpp, show_identifiers): a
// hash of each pixel's value (SHOW_VALUE), or of the draw (SHOW_DRAW: the
// primitive instance) or material (SHOW_MATERIAL) that the visibility
// buffer's triangle identifier names, through its units and the frame's
// instance records. Black where the value is 0 (no geometry).
#include "common/frame.glsl"
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
}
