// Material evaluation: turns a fragment's interpolated vertex data and the
// material's textures and factors (glTF metallic-roughness) into a Surface.
// Shared by every pass that rasterises scene geometry.
#include "surface.glsl"

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
uniform int u_normal_xy_only;       // a two-channel (BC5) normal map: z is rebuilt
uniform int u_normal_green_down;    // DirectX's convention: green points down
uniform int u_double_sided;
uniform int u_unlit;                // KHR_materials_unlit
// Per texture slot (base colour, metallic-roughness, normal, occlusion, emissive):
// the UV set it reads and its KHR_texture_transform matrix.
uniform mat3 u_uv_transform[5];
uniform int u_uv_set[5];

vec2 slot_uv(int slot, vec2 uv0, vec2 uv1) {
  return (u_uv_transform[slot] * vec3(u_uv_set[slot] == 1 ? uv1 : uv0, 1.0)).xy;
}

Surface evaluate_surface(vec3 position, vec3 normal, vec4 tangent, vec2 uv0, vec2 uv1, vec4 color, bool front_facing) {
  Surface s;
  s.position = position;
  vec4 base = texture(u_base_color_texture, slot_uv(0, uv0, uv1)) * u_base_color_factor * color;
  s.albedo = base.rgb;
  s.alpha = base.a;
  s.unlit = u_unlit != 0;
  vec3 n = normalize(normal);
  if (u_double_sided != 0 && !front_facing) n = -n;
  if (u_has_normal_texture != 0) {
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
    vec3 b = cross(n, t) * tangent.w;
    vec3 m = texture(u_normal_texture, slot_uv(2, uv0, uv1)).xyz * 2.0 - 1.0;
    if (u_normal_xy_only != 0) m.z = sqrt(max(1.0 - dot(m.xy, m.xy), 0.0));
    if (u_normal_green_down != 0) m.y = -m.y;
    m.xy *= u_normal_scale;
    n = normalize(mat3(t, b, n) * m);
  }
  s.normal = n;
  vec4 mr = texture(u_metallic_roughness_texture, slot_uv(1, uv0, uv1));
  s.roughness = clamp(mr.g * u_roughness_factor, 0.0, 1.0);
  s.metallic = clamp(mr.b * u_metallic_factor, 0.0, 1.0);
  s.occlusion = mix(1.0, texture(u_occlusion_texture, slot_uv(3, uv0, uv1)).r, u_occlusion_strength);
  s.emissive = texture(u_emissive_texture, slot_uv(4, uv0, uv1)).rgb * u_emissive_factor;
  if (s.unlit) {
    // The base colour is the result: it travels as emission, with nothing to reflect.
    s.emissive = s.albedo;
    s.albedo = vec3(0.0);
    s.metallic = 0.0;
  }
  return s;
}
