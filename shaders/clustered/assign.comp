#version 450 core
// Clustered light assignment, one of two ways (LightIndexList picks per frame).
// Scatter (common/light_scatter.glsl): each light visits
// only the clusters its sphere may reach, the slices its depth range spans
// and, in each, the run of columns and of rows whose boxes overlap it
// (computed, not searched), and passes those whose box it touches; so the cost follows the clusters each light covers,
// not every light for every cluster. With PIXEL_BOUNDS (the default) a
// cluster's box is that of the pixels it holds (mark_active.comp), padded by a
// millimetre per metre for the lighting passes' own reconstruction of those
// positions, and clusters without pixels get no lights. Otherwise the grid's
// boxes, and with ACTIVE_ONLY clusters that hold no visible pixel get none.
// GATHER (common/light_gather.glsl): each cluster tests every light against
// the same box with the same test, so both write the same lists.
#include "common/light_assignment.glsl"
#ifdef GATHER
#include "common/light_gather.glsl"
#else
#include "common/light_scatter.glsl"
#endif
#include "common/clusters.glsl"

struct ClusterBounds {
  vec4 lo;  // view space, xyz
  vec4 hi;
};
layout(std430, binding = 4) readonly buffer Bounds { ClusterBounds u_bounds[]; };
#ifdef ACTIVE_ONLY
layout(std430, binding = 6) readonly buffer Active { uint u_active[]; };
#endif
#ifdef PIXEL_BOUNDS
layout(std430, binding = 6) readonly buffer PixelBounds { uvec4 u_pixel_bounds[]; };
#endif

float pixel_pad(float view_depth) { return 1e-3 * (1.0 + max(view_depth, 0.0)); }

// The box lights are tested against; false when the cluster gets no lights.
bool cluster_box(uint cluster, out ClusterBounds box) {
#ifdef PIXEL_BOUNDS
  uvec4 lo = u_pixel_bounds[cluster], hi = u_pixel_bounds[u_grid.w + cluster];
  box = ClusterBounds(vec4(0.0), vec4(0.0));
  if (lo.x > hi.x) return false;
  vec3 l = vec3(ordered_to_float(lo.x), ordered_to_float(lo.y), ordered_to_float(lo.z));
  vec3 h = vec3(ordered_to_float(hi.x), ordered_to_float(hi.y), ordered_to_float(hi.z));
  vec3 pad = vec3(pixel_pad(-l.z));
  box = ClusterBounds(vec4(l - pad, 0.0), vec4(h + pad, 0.0));
  return true;
#else
  box = u_bounds[cluster];
#ifdef ACTIVE_ONLY
  return u_active[cluster] != 0u;
#else
  return true;
#endif
#endif
}

bool touches(vec4 sphere, ClusterBounds box) {
  if (sphere.w < 0.0) return true;
  vec3 nearest = clamp(sphere.xyz, box.lo.xyz, box.hi.xyz) - sphere.xyz;
  return dot(nearest, nearest) <= sphere.w * sphere.w;
}

#ifdef GATHER
ClusterBounds g_box;

bool gather_bin(uint bin, out vec3 lo, out vec3 hi) {
  bool live = cluster_box(bin, g_box);
  lo = g_box.lo.xyz;
  hi = g_box.hi.xyz;
  return live;
}

bool gather_touches(vec4 sphere) { return touches(sphere, g_box); }
#else
uint cluster_at(uint x, uint y, uint z) { return (z * u_grid.y + y) * u_grid.x + x; }

// The first and last of `cells` columns (or rows) whose grid boxes between
// view depths d0 and d1 reach [lo, hi] (view-space metres), `scale` metres
// per unit of NDC at depth 1 (the grid's frustum is symmetric, as
// gfx::perspective makes it). A cell spanning NDC [a, b] has a box from
// min(a d0, a d1) to max(b d0, b d1) times `scale`, both growing with a and
// b, so each end is one division away; one cell more on each side for rounding.
uvec2 cell_run(float lo, float hi, float d0, float d1, float scale, uint cells) {
  float t = lo / scale, u = hi / scale;
  float least_right = t >= 0.0 ? t / d1 : t / d0;  // a cell's right edge (NDC) must reach this
  float most_left = u >= 0.0 ? u / d0 : u / d1;    // and its left edge must not pass this
  float n = float(cells);
  float first = clamp(ceil((least_right + 1.0) * 0.5 * n) - 2.0, 0.0, n - 1.0);
  float last = clamp(floor((most_left + 1.0) * 0.5 * n) + 1.0, 0.0, n - 1.0);
  return uvec2(first, last);
}

// The slices a light spans, and how far a box may reach past its grid box
// (pixel boxes are padded); false when no cluster can hold it.
bool slice_range(vec4 sphere, out uint first_slice, out uint last_slice, out float reach) {
  first_slice = 0u;
  last_slice = u_grid.z - 1u;
  reach = sphere.w;
  if (sphere.w < 0.0) return true;
  float near_depth = -sphere.z - sphere.w, far_depth = -sphere.z + sphere.w;
  // Wholly behind the near plane (less a pixel box's pad): no box is there.
  if (far_depth < u_near * 0.5) return false;
  reach = sphere.w + 2.0 * pixel_pad(far_depth);
  // One slice more on each side: rounding at slice boundaries and the pad.
  first_slice = uint(max(int(cluster_slice(near_depth)) - 1, 0));
  last_slice = min(cluster_slice(far_depth) + 1u, u_grid.z - 1u);
  return true;
}

// The columns (x) and rows (y) of slice z whose boxes the light may reach.
void slice_cells(vec4 sphere, float reach, uint z, out uvec2 lo, out uvec2 hi) {
  lo = uvec2(0u);
  hi = u_grid.xy - 1u;
  if (sphere.w < 0.0) return;
  // The slice's depths, from any of its boxes.
  ClusterBounds slice = u_bounds[cluster_at(0u, 0u, z)];
  float d0 = -slice.hi.z, d1 = -slice.lo.z;
  uvec2 columns = cell_run(sphere.x - reach, sphere.x + reach, d0, d1, 1.0 / u_projection[0][0], u_grid.x);
  uvec2 rows = cell_run(sphere.y - reach, sphere.y + reach, d0, d1, 1.0 / u_projection[1][1], u_grid.y);
  lo = uvec2(columns.x, rows.x);
  hi = uvec2(columns.y, rows.y);
}

uint cells_in(uvec2 lo, uvec2 hi) { return lo.x > hi.x || lo.y > hi.y ? 0u : (hi.x - lo.x + 1u) * (hi.y - lo.y + 1u); }

// The candidates are each slice's run of columns and rows, numbered slice by
// slice and row by row. Their count is bounded by the slices times the first
// slice's cells: the nearest slice sees the light widest.
uint candidate_count(vec4 sphere) {
  uint first_slice, last_slice;
  float reach;
  if (!slice_range(sphere, first_slice, last_slice, reach)) return 0u;
  uvec2 lo, hi;
  slice_cells(sphere, reach, first_slice, lo, hi);
  return (last_slice - first_slice + 1u) * cells_in(lo, hi);
}

uint for_each_bin(vec4 sphere, uint first, uint stride) {
  uint first_slice, last_slice;
  float reach;
  if (!slice_range(sphere, first_slice, last_slice, reach)) return 0u;
  uint visited = 0u, base = 0u;  // base: the number of the slice's first candidate
  for (uint z = first_slice; z <= last_slice; ++z) {
    uvec2 lo, hi;
    slice_cells(sphere, reach, z, lo, hi);
    uint width = hi.x - lo.x + 1u, count = cells_in(lo, hi);
    // This slice's first candidate numbered first + k * stride.
    for (uint c = (first + stride - base % stride) % stride; c < count; c += stride) {
      uint cluster = cluster_at(lo.x + c % width, lo.y + c / width, z);
      ClusterBounds box;
      if (!cluster_box(cluster, box) || !touches(sphere, box)) continue;
      visit_bin(cluster);
      ++visited;
    }
    base += count;
  }
  return visited;
}
#endif
