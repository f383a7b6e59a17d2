#version 450 core
// Heatmap of lights evaluated per pixel in the current mode, from the counts
// the lighting shaders wrote with COUNT_LIGHTS: black where none, otherwise the
// colour map on a log scale that tops out at u_scale_max evaluations.
#include "common/colour_map.glsl"

layout(r32ui, binding = 0) uniform readonly uimage2D u_light_counts;
uniform float u_scale_max;

layout(location = 0) out vec4 out_color;

void main() {
  out_color = vec4(count_colour(imageLoad(u_light_counts, ivec2(gl_FragCoord.xy)).r, u_scale_max), 1.0);
}
