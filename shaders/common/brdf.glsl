// Cook-Torrance BRDF with glTF's metallic-roughness inputs: GGX normal
// distribution, height-correlated Smith visibility, Schlick Fresnel and a
// Lambert diffuse lobe weighted by what the specular lobe does not reflect.
const float kPi = 3.14159265358979;

float distribution_ggx(float n_dot_h, float alpha) {
  float a2 = alpha * alpha;
  float f = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (kPi * f * f);
}

float visibility_smith_ggx_correlated(float n_dot_v, float n_dot_l, float alpha) {
  float a2 = alpha * alpha;
  float ggx_v = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
  float ggx_l = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
  return 0.5 / max(ggx_v + ggx_l, 1e-6);
}

vec3 fresnel_schlick(float cos_theta, vec3 f0) {
  return f0 + (1.0 - f0) * pow(1.0 - cos_theta, 5.0);
}

// Outgoing radiance towards V for unit incoming radiance from L, times N.L.
vec3 brdf_cook_torrance(vec3 n, vec3 v, vec3 l, vec3 albedo, float metallic, float roughness) {
  float n_dot_l = max(dot(n, l), 0.0);
  if (n_dot_l <= 0.0) return vec3(0.0);
  vec3 h = normalize(v + l);
  float n_dot_v = max(dot(n, v), 1e-4);
  float n_dot_h = max(dot(n, h), 0.0);
  float v_dot_h = max(dot(v, h), 0.0);
  float alpha = max(roughness * roughness, 2e-3);
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
  vec3 f = fresnel_schlick(v_dot_h, f0);
  vec3 specular = distribution_ggx(n_dot_h, alpha) * visibility_smith_ggx_correlated(n_dot_v, n_dot_l, alpha) * f;
  vec3 diffuse = (1.0 - f) * (1.0 - metallic) * albedo / kPi;
  return (diffuse + specular) * n_dot_l;
}
