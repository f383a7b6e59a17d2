// Surface response to one light, for the three shading models chosen with
// --shading (compiled in through SHADING_MODEL; identical in every technique):
//   0 pbr:          Cook-Torrance with glTF's metallic-roughness inputs: GGX
//                   distribution, height-correlated Smith visibility, Schlick
//                   Fresnel, Lambert diffuse weighted by what is not reflected.
//   1 blinn-phong:  diffuse max(N.L, 0) + specular max(N.H, 0)^shininess
//   2 phong:        diffuse max(N.L, 0) + specular max(R.V, 0)^shininess, R = reflect(-L, N)
// The Phong models take the same material: diffuse colour albedo * (1 - metallic),
// specular colour mix(0.04, albedo, metallic), shininess 2 / roughness^4 - 2; the
// lobes carry the usual energy normalisation (1/pi, (n + 2) / 2pi or (n + 8) / 8pi)
// so that the three models light a scene equally bright.
#ifndef SHADING_MODEL
#define SHADING_MODEL 0
#endif
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

// Schlick's weight (1 - cos)^5: Fresnel's F = f0 + (1 - f0) * weight. By
// multiplication: pow() is exp2(log2()) on software rasterisers.
float fresnel_weight(float cos_theta) {
  float m = 1.0 - cos_theta;
  float m2 = m * m;
  return m2 * m2 * m;
}

// Every model's response to one light is written as three factors that do not
// depend on the material's colours (brdf_terms), times the material
// (brdf_combine). The combination is linear, so a light pre-pass can sum each
// factor over lights first and combine once per pixel with the same result.
// Cook-Torrance: with E = N.L and w = (1 - V.H)^5, Schlick's F = f0 (1 - w) + w
// and 1 - F = (1 - f0)(1 - w), so
//   diffuse  = (1 - f0)(1 - metallic) albedo / pi * [E (1 - w)]
//   specular = f0 * [E D Vis (1 - w)] + [E D Vis w]
// The Phong models: diffuse = albedo (1 - metallic) / pi * [E],
// specular = specular colour * [E lobe], and the third factor is zero.
// brdf_terms returns the bracketed factors as x (diffuse), y (specular times
// f0) and z (specular independent of f0).
vec3 brdf_terms(vec3 n, vec3 v, vec3 l, float roughness) {
  float n_dot_l = max(dot(n, l), 0.0);
  if (n_dot_l <= 0.0) return vec3(0.0);
  float alpha = max(roughness * roughness, 2e-3);
#if SHADING_MODEL == 0
  vec3 h = normalize(v + l);
  float n_dot_v = max(dot(n, v), 1e-4);
  float n_dot_h = max(dot(n, h), 0.0);
  float w = fresnel_weight(max(dot(v, h), 0.0));
  float lobe = distribution_ggx(n_dot_h, alpha) * visibility_smith_ggx_correlated(n_dot_v, n_dot_l, alpha) * n_dot_l;
  return vec3(n_dot_l * (1.0 - w), lobe * (1.0 - w), lobe * w);
#else
  float shininess = clamp(2.0 / (alpha * alpha) - 2.0, 1.0, 8192.0);
#if SHADING_MODEL == 1
  float lobe = pow(max(dot(n, normalize(v + l)), 0.0), shininess) * (shininess + 8.0) / (8.0 * kPi);
#else
  float lobe = pow(max(dot(reflect(-l, n), v), 0.0), shininess) * (shininess + 2.0) / (2.0 * kPi);
#endif
  return vec3(n_dot_l, lobe * n_dot_l, 0.0);
#endif
}

// The diffuse and specular light a surface reflects towards V, from the factors
// of brdf_terms (for one light, or summed over many) times the light's
// radiance.
void brdf_combine(vec3 diffuse_term, vec3 specular_f0_term, vec3 specular_term, vec3 albedo, float metallic,
                  out vec3 diffuse, out vec3 specular) {
  vec3 f0 = mix(vec3(0.04), albedo, metallic);
#if SHADING_MODEL == 0
  diffuse = (1.0 - f0) * (1.0 - metallic) * albedo / kPi * diffuse_term;
#else
  diffuse = (1.0 - metallic) * albedo / kPi * diffuse_term;
#endif
  specular = f0 * specular_f0_term + specular_term;
}

// Outgoing radiance towards V for unit incoming radiance from L, times N.L, as
// the diffuse and the specular lobe's shares (their sum is the response).
void surface_response_split(vec3 n, vec3 v, vec3 l, vec3 albedo, float metallic, float roughness, out vec3 diffuse,
                            out vec3 specular) {
  vec3 t = brdf_terms(n, v, l, roughness);
  brdf_combine(vec3(t.x), vec3(t.y), vec3(t.z), albedo, metallic, diffuse, specular);
}

vec3 surface_response(vec3 n, vec3 v, vec3 l, vec3 albedo, float metallic, float roughness) {
  vec3 diffuse, specular;
  surface_response_split(n, v, l, albedo, metallic, roughness, diffuse, specular);
  return diffuse + specular;
}
