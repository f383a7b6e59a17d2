// Material evaluation: turns a fragment's interpolated vertex data and the
// material's textures and factors (glTF metallic-roughness) into a Surface.
// Shared by every pass that rasterises scene geometry and, with
// EXPLICIT_GRADIENTS, by the visibility buffer's compute resolve, which has no
// quads to take derivatives from: it sets g_uv_dx and g_uv_dy (per texture
// slot, the coordinates' change to the next pixel right and up) before
// evaluate_material, so that mip levels match the raster path's.
#include "surface.glsl"

#ifdef BINDLESS_TEXTURES
// With BINDLESS_TEXTURES (and EXPLICIT_GRADIENTS: the visibility buffer's
// one-dispatch resolve) each slot is sampled through the material's handle,
// not a bound unit; the caller keeps `material` dynamically uniform
// (ARB_bindless_texture asks it). Five handles a material, by slot; C++ twin:
// MaterialTextures in src/render/techniques/visibility/visibility.hpp.
layout(std430, binding = 29) readonly buffer MaterialTextures { uvec2 u_material_textures[]; };
#define SLOT_SAMPLER(sampler, slot) sampler2D(u_material_textures[material * 5u + uint(slot)])
#else
#define SLOT_SAMPLER(sampler, slot) sampler
layout(binding = 0) uniform sampler2D u_base_color_texture;
layout(binding = 1) uniform sampler2D u_metallic_roughness_texture;
layout(binding = 2) uniform sampler2D u_normal_texture;
layout(binding = 3) uniform sampler2D u_occlusion_texture;
layout(binding = 4) uniform sampler2D u_emissive_texture;
#endif

#ifdef EXPLICIT_GRADIENTS
vec2 g_uv_dx[5], g_uv_dy[5];
#define SAMPLE_SLOT(sampler, slot, uv) textureGrad(SLOT_SAMPLER(sampler, slot), uv, g_uv_dx[slot], g_uv_dy[slot])
#else
#define SAMPLE_SLOT(sampler, slot, uv) texture(SLOT_SAMPLER(sampler, slot), uv)
#endif

#include "material_table.glsl"

// uv: per texture slot, its coordinates (mesh.vert's v_uv). `flags` is
// Material.flags, passed apart so that fragment shaders branch on a value
// that agrees across a pixel quad.
Surface evaluate_material(uint material, uint flags, vec3 position, vec3 normal, vec4 tangent, vec2 uv[5], vec4 color, bool front_facing) {
  Material m = material_at(material);
  Surface s;
  s.position = position;
  // Each factor lies in [0, 1] (glTF), but with MSAA a silhouette pixel's vertex
  // colour is extrapolated from its centre off the triangle; clamped, as the
  // G-buffer's 8-bit albedo stores it, so forward and deferred agree there.
  vec4 base = clamp(SAMPLE_SLOT(u_base_color_texture, 0, uv[0]) * m.base_color_factor * color, 0.0, 1.0);
  s.albedo = base.rgb;
  s.alpha = base.a;
  s.unlit = (flags & kMaterialUnlit) != 0u;
  vec3 n = normalize(normal);
  if ((flags & kMaterialDoubleSided) != 0u && !front_facing) n = -n;
  if ((flags & kMaterialHasNormalTexture) != 0u) {
    vec3 t = normalize(tangent.xyz - n * dot(n, tangent.xyz));
    vec3 b = cross(n, t) * tangent.w;
    vec3 tn = SAMPLE_SLOT(u_normal_texture, 2, uv[2]).xyz * 2.0 - 1.0;
    if ((flags & kMaterialNormalXyOnly) != 0u) tn.z = sqrt(max(1.0 - dot(tn.xy, tn.xy), 0.0));
    if ((flags & kMaterialNormalGreenDown) != 0u) tn.y = -tn.y;
    tn.xy *= m.emissive.a;  // the normal scale
    n = normalize(mat3(t, b, n) * tn);
  }
  s.normal = n;
  vec4 mr = SAMPLE_SLOT(u_metallic_roughness_texture, 1, uv[1]);
  s.roughness = clamp(mr.g * m.roughness_factor, 0.0, 1.0);
  s.metallic = clamp(mr.b * m.metallic_factor, 0.0, 1.0);
  s.occlusion = mix(1.0, SAMPLE_SLOT(u_occlusion_texture, 3, uv[3]).r, m.occlusion_strength);
  s.emissive = SAMPLE_SLOT(u_emissive_texture, 4, uv[4]).rgb * m.emissive.rgb;
  if (s.unlit) {
    // The base colour is the result: it travels as emission, with nothing to reflect.
    s.emissive = s.albedo;
    s.albedo = vec3(0.0);
    s.metallic = 0.0;
  }
  return s;
}

#ifndef EXPLICIT_GRADIENTS
// The fragment's material: its index and flags come flat from mesh.vert's
// instance record, its texture coordinates (v_uv) ready per slot.
#include "mesh_interface.glsl"

// < 0 when the fragment's material is not alpha-masked.
float material_alpha_cutoff() { return material_at(v_material).alpha_cutoff; }

Surface evaluate_surface(vec3 position, vec3 normal, vec4 tangent, vec2 uv[5], vec4 color, bool front_facing) {
  return evaluate_material(v_material, v_material_flags, position, normal, tangent, uv, color, front_facing);
}
#endif
