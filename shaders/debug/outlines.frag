#version 450 core
// Light-volume outlines: draws over the lit image where each light's sphere
// meets the scene, a line about one pixel wide in the light's hue.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/lights.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  bool covered = read_gbuffer(ivec2(gl_FragCoord.xy), s);
  vec3 hue_sum = vec3(0.0);
  float lines = 0.0;
  // Derivatives stay defined: every pixel of a quad runs the same loop, and
  // the light kind is the same for all of them.
  for (uint i = 0u; i < u_light_count; ++i) {
    Light light = light_at(i);
    if (uint(light.color_kind.w) == kLightDirectional) continue;
    // Signed distance to the sphere; its change across a pixel sets the width.
    float edge = distance(light.position_radius.xyz, s.position) - light.position_radius.w;
    if (abs(edge) < fwidth(edge)) {
      hue_sum += light.color_kind.rgb / max(max(light.color_kind.r, light.color_kind.g), max(light.color_kind.b, 1e-6));
      lines += 1.0;
    }
  }
  if (!covered || lines == 0.0) discard;
  out_color = vec4(hue_sum / lines, 1.0);
}
