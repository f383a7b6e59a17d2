#version 450 core
// Depth-only passes over surfaces without an alpha test (with common/mesh.vert
// built with POSITION_ONLY): the fixed-function depth write is the pass's
// output; the shader exists so that the fragments debug view counts them too,
// and for the shading depth of clustered forward+ with MSAA.
#include "common/fragment_count.glsl"
#include "common/shading_depth.glsl"

void main() {
  count_fragment();
  write_shading_depth();
}
