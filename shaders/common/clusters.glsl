// The cluster grid shared by the clustered techniques: the view frustum cut into
// u_grid.x * u_grid.y screen tiles and u_grid.z depth slices. Slice 0 runs from
// the near plane to u_slicing.x; past it a depth's slice is f(depth) * scale + bias,
// f the logarithm (log and plain-log slicing: distant slices are not wasted)
// or, for uniform slicing, the depth itself. C++ twin: ClusterGrid in
// src/render/lighting/cluster_grid.cpp (tested against each other).
layout(std140, binding = 1) uniform ClusterBlock {
  uvec4 u_grid;             // xyz clusters per axis, w total
  vec4 u_slicing;           // x first slice's far depth, y scale, z bias, w 1 = uniform (else log)
};

#include "light_lists.glsl"

// The slice of a positive view depth (metres in front of the camera). Depths
// at or before the near plane fall in slice 0, at or beyond the far plane in
// the last slice: every visible fragment has a valid cluster.
uint cluster_slice(float view_depth) {
  if (view_depth <= u_slicing.x) return 0u;
  float slice = (u_slicing.w > 0.5 ? view_depth : log(view_depth)) * u_slicing.y + u_slicing.z;
  return uint(clamp(slice, 1.0, float(u_grid.z - 1u)));
}

uint cluster_index(vec2 frag_coord, vec2 viewport, float view_depth) {
  uvec2 tile = uvec2(clamp(frag_coord / viewport * vec2(u_grid.xy), vec2(0.0), vec2(u_grid.xy) - 1.0));
  return (cluster_slice(view_depth) * u_grid.y + tile.y) * u_grid.x + tile.x;
}

// Floats as unsigned integers that sort like the floats, so that atomicMin and
// atomicMax on them keep the least and greatest float (pixel bounds).
uint float_to_ordered(float f) {
  uint bits = floatBitsToUint(f);
  return (bits & 0x80000000u) != 0u ? ~bits : (bits | 0x80000000u);
}
float ordered_to_float(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u); }
