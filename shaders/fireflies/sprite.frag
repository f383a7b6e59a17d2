#version 450 core
// A firefly's glow, added to the lit HDR image (blend one, one): a bright
// core fading out to the quad's inscribed circle.
in vec2 v_corner;
flat in vec3 v_color;

layout(location = 0) out vec4 o_color;

void main() {
  float r2 = dot(v_corner, v_corner);
  if (r2 >= 1.0) discard;
  float glow = exp(-6.0 * r2) - exp(-6.0);
  o_color = vec4(v_color * 8.0 * glow, 0.0);
}
