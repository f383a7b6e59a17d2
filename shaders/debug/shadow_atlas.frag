#version 450 core
// Shadow-atlas view: the atlas's depth texture (every shadowed light's cube
// faces, cones and cascades, each in its tile) in a square at the left of the
// image, brighter where a caster is nearer its light (reversed Z, fourth root
// so that the distant end stays visible); empty tiles are black.
#include "common/frame.glsl"

layout(binding = 0) uniform sampler2D u_atlas;  // read as plain depth: the view's sampler turns comparison off

layout(location = 0) out vec4 out_color;

void main() {
  vec2 uv = gl_FragCoord.xy / u_viewport_size.y;
  if (uv.x > 1.0) {
    out_color = vec4(0.15, 0.15, 0.15, 1.0);
    return;
  }
  float depth = texture(u_atlas, uv).r;
  out_color = vec4(vec3(pow(max(depth, 0.0), 0.25)), 1.0);
}
