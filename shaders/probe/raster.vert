#version 450 core
// Raster probe, raster side (gfx/stage_probe.hpp): the triangles' positions
// are clip-space already (w = 1, z the depth in Atrium's convention,
// gfx/depth.hpp), as small as the visibility buffer's triangles of a dense
// scene; nothing else is computed, as in its geometry pass.
#include "common/clip.glsl"

layout(location = 0) in vec3 a_position;

void main() {
  gl_Position = clip_position(vec4(a_position, 1.0));
}
