#version 450 core
// Raster probe, raster side (gfx/stage_probe.hpp): the triangles' positions
// are clip-space already (w = 1), as small as the visibility buffer's
// triangles of a dense scene; nothing else is computed, as in its geometry pass.
layout(location = 0) in vec3 a_position;

void main() {
  gl_Position = vec4(a_position, 1.0);
}
