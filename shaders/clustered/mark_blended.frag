#version 450 core
// Clustered modes, before mark_active.comp and light assignment: marks the
// clusters of blended fragments in front of the opaque depth (tested, not
// written), so that the lists the transparency pass reads hold the lights that
// reach glass floating where no opaque pixel is.
#include "common/frame.glsl"
#include "common/clusters.glsl"
#include "common/cluster_marks.glsl"

// Only fragments the depth test keeps may mark: run the test first.
layout(early_fragment_tests) in;

#include "common/mesh_interface.glsl"

void main() {
  // The view position and cluster as shade_cluster_lights computes them.
  vec3 p = (u_view * vec4(v_position, 1.0)).xyz;
  mark_cluster(cluster_index(gl_FragCoord.xy, u_viewport_size, -p.z), p);
}
