// Material evaluation: turns a fragment's interpolated vertex data and the
// material's textures and factors into the inputs of shading. Shared by every
// pass that rasterises scene geometry.
struct Surface {
  vec3 position;
  vec3 normal;
  vec3 albedo;
  float alpha;
  float metallic;
  float roughness;
  float occlusion;
  vec3 emissive;
};

layout(binding = 0) uniform sampler2D u_base_color_texture;
layout(binding = 1) uniform sampler2D u_metallic_roughness_texture;
layout(binding = 2) uniform sampler2D u_normal_texture;
layout(binding = 3) uniform sampler2D u_occlusion_texture;
layout(binding = 4) uniform sampler2D u_emissive_texture;

uniform vec4 u_base_color_factor;
uniform float u_metallic_factor;
uniform float u_roughness_factor;
uniform vec3 u_emissive_factor;     // already multiplied by emissive strength
uniform float u_normal_scale;
uniform float u_occlusion_strength;
uniform float u_alpha_cutoff;       // < 0 when the material is not alpha-masked
uniform int u_has_normal_texture;
uniform int u_double_sided;

Surface evaluate_surface(vec3 position, vec3 normal, vec4 tangent, vec2 uv, bool front_facing) {
  Surface s;
  s.position = position;
  vec4 base = texture(u_base_color_texture, uv) * u_base_color_factor;
  s.albedo = base.rgb;
  s.alpha = base.a;
  vec3 n = normalize(normal);
  if (u_double_sided != 0 && !front_facing) n = -n;
  if (u_has_normal_texture != 0) {
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
    vec3 b = cross(n, t) * tangent.w;
    vec3 m = texture(u_normal_texture, uv).xyz * 2.0 - 1.0;
    m.xy *= u_normal_scale;
    n = normalize(mat3(t, b, n) * m);
  }
  s.normal = n;
  vec4 mr = texture(u_metallic_roughness_texture, uv);
  s.roughness = clamp(mr.g * u_roughness_factor, 0.0, 1.0);
  s.metallic = clamp(mr.b * u_metallic_factor, 0.0, 1.0);
  s.occlusion = mix(1.0, texture(u_occlusion_texture, uv).r, u_occlusion_strength);
  s.emissive = texture(u_emissive_texture, uv).rgb * u_emissive_factor;
  return s;
}
