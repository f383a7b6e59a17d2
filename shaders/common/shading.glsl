// Light evaluation shared by every technique: what one point light adds to a
// surface seen from the camera, and the terms that do not depend on lights.
#include "attenuation.glsl"
#include "brdf.glsl"
#include "lights.glsl"

vec3 shade_point_light(Surface s, vec3 v, PointLight light) {
  vec3 to_light = light.position_radius.xyz - s.position;
  float distance = length(to_light);
  float attenuation = light_attenuation(distance, light.position_radius.w);
  if (attenuation <= 0.0) return vec3(0.0);
  vec3 l = to_light / max(distance, 1e-6);
  return brdf_cook_torrance(s.normal, v, l, s.albedo, s.metallic, s.roughness) * light.color.rgb * attenuation;
}

vec3 shade_unlit_terms(Surface s, vec3 ambient) {
  return ambient * s.albedo * s.occlusion + s.emissive;
}
