// The debug heatmaps' colour map: viridis (sampled at nine stops from
// matplotlib's definition), perceptually uniform and rising steadily in
// lightness, so that counts read in order at a glance and in greyscale.
// Zero and overflow are drawn in colours of their own, outside the map.
const vec3 kHeatmapZero = vec3(0.0);
const vec3 kHeatmapOverflow = vec3(1.0, 0.0, 1.0);

vec3 colour_map(float t) {
  const vec3 kStops[9] = vec3[](vec3(0.267, 0.005, 0.329), vec3(0.279, 0.175, 0.483), vec3(0.230, 0.322, 0.546),
                                vec3(0.173, 0.449, 0.558), vec3(0.128, 0.567, 0.551), vec3(0.158, 0.684, 0.502),
                                vec3(0.369, 0.789, 0.383), vec3(0.678, 0.864, 0.190), vec3(0.993, 0.906, 0.144));
  float x = clamp(t, 0.0, 1.0) * 8.0;
  int i = min(int(x), 7);
  return mix(kStops[i], kStops[i + 1], x - float(i));
}

// A count on a log scale that reaches the top of the map at `scale_max`.
vec3 count_colour(uint count, float scale_max) {
  if (count == 0u) return kHeatmapZero;
  return colour_map(log2(1.0 + float(count)) / log2(1.0 + max(scale_max, 1.0)));
}
