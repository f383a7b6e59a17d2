#version 450 core
// Light pre-pass, light buffer: reads normal, roughness and position from the
// thin G-buffer and adds one light's BRDF factors (brdf_terms) times its
// radiance to the three light-buffer targets, blended additively. Drawn on a
// light's volume, or with DIRECTIONAL_ONLY as a full-screen pass for one
// directional light (u_light_index; one pass each, rather than a loop over
// every light that llvmpipe would run in full). No material is known yet: the
// second geometry pass multiplies the sums by it (shade.frag).
#include "common/frame.glsl"
#include "common/surface.glsl"
#include "common/gbuffer.glsl"
#include "common/shading.glsl"

#ifdef DIRECTIONAL_ONLY
uniform uint u_light_index;
#else
flat in uint v_light;
#endif

// Counting has side effects, which make GL run the shader before the depth
// test; count only what passes it, as a GPU's early tests would.
#ifdef COUNT_LIGHTS
layout(early_fragment_tests) in;
#endif

layout(location = 0) out vec4 out_diffuse;
layout(location = 1) out vec4 out_specular_f0;
layout(location = 2) out vec4 out_specular;

vec3 g_diffuse = vec3(0.0), g_specular_f0 = vec3(0.0), g_specular = vec3(0.0);

// `shadowed`: look the light's maps up (constant where the caller knows).
void accumulate(Surface s, vec3 v, Light light, bool shadowed) {
  count_light_evaluation();
  vec3 l;
  vec3 radiance = incoming_light(s, light, l, shadowed);
  if (all(lessThanEqual(radiance, vec3(0.0)))) return;
  vec3 t = brdf_terms(s.normal, v, l, s.roughness);
  g_diffuse += t.x * radiance;
  g_specular_f0 += t.y * radiance;
  g_specular += t.z * radiance;
}

void main() {
  Surface s;
  if (!read_gbuffer(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 v = normalize(u_camera_position.xyz - s.position);
#ifdef DIRECTIONAL_ONLY
  accumulate(s, v, light_at(u_light_index), has_shadow_maps(light_at(u_light_index)));
#else
  accumulate(s, v, light_at(v_light), kShadowedLights);
#endif
  out_diffuse = vec4(g_diffuse, 0.0);
  out_specular_f0 = vec4(g_specular_f0, 0.0);
  out_specular = vec4(g_specular, 0.0);
}
