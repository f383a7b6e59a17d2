#version 450 core
// Heatmap of lights evaluated per pixel in the current mode, from the counts
// the lighting shaders wrote with COUNT_LIGHTS. Zero is black; otherwise a
// colour map from dark blue to red on a log scale that reaches red at
// u_scale_max evaluations.
layout(r32ui, binding = 0) uniform readonly uimage2D u_light_counts;
uniform float u_scale_max;

layout(location = 0) out vec4 out_color;

// A colour map that rises steadily in lightness and runs through distinct
// hues (dark blue, blue, cyan, green, yellow, orange, red), so that counts read
// in order at a glance.
vec3 colour_map(float t) {
  const vec3 kStops[7] = vec3[](vec3(0.10, 0.05, 0.35), vec3(0.15, 0.30, 0.90), vec3(0.10, 0.75, 0.90),
                                vec3(0.25, 0.85, 0.35), vec3(0.95, 0.90, 0.20), vec3(0.98, 0.55, 0.10),
                                vec3(0.85, 0.10, 0.10));
  float x = clamp(t, 0.0, 1.0) * 6.0;
  int i = min(int(x), 5);
  return mix(kStops[i], kStops[i + 1], x - float(i));
}

void main() {
  uint count = imageLoad(u_light_counts, ivec2(gl_FragCoord.xy)).r;
  if (count == 0u) {
    out_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  float t = log2(1.0 + float(count)) / log2(1.0 + max(u_scale_max, 1.0));
  out_color = vec4(colour_map(t), 1.0);
}
