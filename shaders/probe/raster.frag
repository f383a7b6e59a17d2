#version 450 core
// Raster probe, raster side: what the visibility buffer's geometry pass
// writes, the triangle's identifier (its index in the one draw) behind the
// depth test.
layout(location = 0) out uint o_id;

void main() {
  o_id = uint(gl_PrimitiveID);
}
