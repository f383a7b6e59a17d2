// Marks what a cluster holds before light assignment reads it: by default
// (--cluster-bounds pixels) grows the cluster's view-space box to a point (least
// and greatest x, y, z as ordered integers; untouched clusters stay empty); with
// ACTIVE_FLAGS (--cluster-bounds grid --active-clusters) only flags the cluster.
// Written by the depth-buffer pass (mark_active.comp) and by blended surfaces
// (mark_blended.frag). Needs clusters.glsl.
#ifdef ACTIVE_FLAGS
layout(std430, binding = 6) writeonly buffer Active { uint u_active[]; };
#else
// [0, clusters): least xyz; [clusters, 2 * clusters): greatest xyz.
layout(std430, binding = 6) buffer PixelBounds { uvec4 u_pixel_bounds[]; };
#endif

void mark_cluster(uint cluster, vec3 view_position) {
#ifdef ACTIVE_FLAGS
  u_active[cluster] = 1u;
#else
  uvec3 ordered = uvec3(float_to_ordered(view_position.x), float_to_ordered(view_position.y), float_to_ordered(view_position.z));
  atomicMin(u_pixel_bounds[cluster].x, ordered.x);
  atomicMin(u_pixel_bounds[cluster].y, ordered.y);
  atomicMin(u_pixel_bounds[cluster].z, ordered.z);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].x, ordered.x);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].y, ordered.y);
  atomicMax(u_pixel_bounds[u_grid.w + cluster].z, ordered.z);
#endif
}
