#version 450 core
// Clustered deferred lighting: reads each pixel's surface from the G-buffer,
// finds its cluster from screen position and view depth, and shades it with
// that cluster's lights only.
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/cluster_shading.glsl"

layout(location = 0) out vec4 out_color;

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) {
    out_color = vec4(u_background.rgb, 1.0);
    return;
  }
  out_color = vec4(shade_cluster_lights(s, gl_FragCoord.xy), 1.0);
}
