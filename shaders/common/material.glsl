// Material evaluation: turns a fragment's interpolated vertex data and the
// material's textures and factors (glTF metallic-roughness) into a Surface.
// Shared by every pass that rasterises scene geometry.
#include "surface.glsl"

layout(binding = 0) uniform sampler2D u_base_color_texture;
layout(binding = 1) uniform sampler2D u_metallic_roughness_texture;
layout(binding = 2) uniform sampler2D u_normal_texture;
layout(binding = 3) uniform sampler2D u_occlusion_texture;
layout(binding = 4) uniform sampler2D u_emissive_texture;

// The fragment's material: its index and flags come flat from mesh.vert's
// instance record, its texture coordinates (v_uv) ready per slot.
#include "material_table.glsl"
flat in uint v_material;
flat in uint v_material_flags;

// < 0 when the fragment's material is not alpha-masked.
float material_alpha_cutoff() { return material_at(v_material).alpha_cutoff; }

// uv: per texture slot, its coordinates (mesh.vert's v_uv).
Surface evaluate_surface(vec3 position, vec3 normal, vec4 tangent, vec2 uv[5], vec4 color, bool front_facing) {
  Material m = material_at(v_material);
  uint flags = v_material_flags;
  Surface s;
  s.position = position;
  // Each factor lies in [0, 1] (glTF), but with MSAA a silhouette pixel's vertex
  // colour is extrapolated from its centre off the triangle; clamped, as the
  // G-buffer's 8-bit albedo stores it, so forward and deferred agree there.
  vec4 base = clamp(texture(u_base_color_texture, uv[0]) * m.base_color_factor * color, 0.0, 1.0);
  s.albedo = base.rgb;
  s.alpha = base.a;
  s.unlit = (flags & kMaterialUnlit) != 0u;
  vec3 n = normalize(normal);
  if ((flags & kMaterialDoubleSided) != 0u && !front_facing) n = -n;
  if ((flags & kMaterialHasNormalTexture) != 0u) {
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
    vec3 b = cross(n, t) * tangent.w;
    vec3 tn = texture(u_normal_texture, uv[2]).xyz * 2.0 - 1.0;
    if ((flags & kMaterialNormalXyOnly) != 0u) tn.z = sqrt(max(1.0 - dot(tn.xy, tn.xy), 0.0));
    if ((flags & kMaterialNormalGreenDown) != 0u) tn.y = -tn.y;
    tn.xy *= m.emissive.a;  // the normal scale
    n = normalize(mat3(t, b, n) * tn);
  }
  s.normal = n;
  vec4 mr = texture(u_metallic_roughness_texture, uv[1]);
  s.roughness = clamp(mr.g * m.roughness_factor, 0.0, 1.0);
  s.metallic = clamp(mr.b * m.metallic_factor, 0.0, 1.0);
  s.occlusion = mix(1.0, texture(u_occlusion_texture, uv[3]).r, m.occlusion_strength);
  s.emissive = texture(u_emissive_texture, uv[4]).rgb * m.emissive.rgb;
  if (s.unlit) {
    // The base colour is the result: it travels as emission, with nothing to reflect.
    s.emissive = s.albedo;
    s.albedo = vec3(0.0);
    s.metallic = 0.0;
  }
  return s;
}
