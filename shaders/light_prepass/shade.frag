#version 450 core
// Light pre-pass, material pass: the second geometry pass. Evaluates each
// visible fragment's material and multiplies the light buffer's sums at its
// pixel by it (brdf_combine), plus ambient and emission; writes the lit HDR
// image (and, split, the diffuse and specular sums). Depth is already there:
// only the visible fragment passes the test. With MSAA, PER_SAMPLE builds the
// edge pixels' variant, which reads the light of each sample.
#include "common/frame.glsl"
// Before material.glsl, which includes it inside a conditional block.
#include "common/mesh_interface.glsl"
#include "common/material.glsl"
#include "common/fragment_count.glsl"
#include "common/lighting_targets.glsl"
#include "common/msaa.glsl"

layout(binding = 5) uniform target2D u_light_diffuse;
layout(binding = 6) uniform target2D u_light_specular_f0;
layout(binding = 7) uniform target2D u_light_specular;

void main() {
  count_fragment();
  Surface s = evaluate_surface(v_position, v_normal, v_tangent, v_uv, v_color, gl_FrontFacing);
  if (s.alpha < material_alpha_cutoff()) discard;
  LightSum sum = no_light();
  if (!s.unlit) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 diffuse, specular;
    brdf_combine(fetch_sample(u_light_diffuse, pixel, kThisSample).rgb, fetch_sample(u_light_specular_f0, pixel, kThisSample).rgb,
                 fetch_sample(u_light_specular, pixel, kThisSample).rgb, s.albedo, s.metallic, diffuse, specular);
    sum = light_sum(diffuse, specular);
  }
  write_lighting(shade_unlit_terms(s, u_ambient.rgb), sum);
}
