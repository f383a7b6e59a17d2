#version 450 core
// One triangle that covers the screen; passes UVs in [0, 1] to full-screen passes.
#include "common/clip.glsl"

out vec2 v_uv;

void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = p;
  gl_Position = clip_position(vec4(p * 2.0 - 1.0, 0.0, 1.0));
}
