// The full G-buffer of the deferred techniques (reference layout), written by
// the geometry pass and read back into a Surface by lighting passes. C++ side:
// GBuffer in src/systems/lighting/gbuffer.cpp (formats, bytes per pixel).
//   0 position           RGBA32F      xyz world position, w = 1 where geometry was drawn
//   1 albedo, occlusion  SRGB8_ALPHA8 rgb base colour, a ambient occlusion
//   2 normal             RGBA16       xyz world-space shading normal * 0.5 + 0.5 (16-bit
//                                     unorm: 3e-5 steps; half floats' 1e-3 near 1 moved
//                                     sharp GGX highlights visibly)
//   3 metal-rough        RGBA8        r metallic, g roughness
//   4 emissive           RGBA16F      rgb emitted radiance
#ifdef GBUFFER_WRITE
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out vec4 out_normal;
layout(location = 3) out vec4 out_metallic_roughness;
layout(location = 4) out vec4 out_emissive;

void write_gbuffer(Surface s) {
  out_position = vec4(s.position, 1.0);
  out_albedo = vec4(s.albedo, s.occlusion);
  out_normal = vec4(s.normal * 0.5 + 0.5, 0.0);
  out_metallic_roughness = vec4(s.metallic, s.roughness, 0.0, 0.0);
  out_emissive = vec4(s.emissive, 0.0);
}
#else
layout(binding = 0) uniform sampler2D u_gbuffer_position;
layout(binding = 1) uniform sampler2D u_gbuffer_albedo;
layout(binding = 2) uniform sampler2D u_gbuffer_normal;
layout(binding = 3) uniform sampler2D u_gbuffer_metallic_roughness;
layout(binding = 4) uniform sampler2D u_gbuffer_emissive;

// False where no geometry covers the pixel (the background shows).
bool read_gbuffer(ivec2 pixel, out Surface s) {
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w == 0.0) return false;
  vec4 albedo = texelFetch(u_gbuffer_albedo, pixel, 0);
  vec4 mr = texelFetch(u_gbuffer_metallic_roughness, pixel, 0);
  s.position = position.xyz;
  s.normal = texelFetch(u_gbuffer_normal, pixel, 0).xyz * 2.0 - 1.0;
  s.albedo = albedo.rgb;
  s.alpha = 1.0;
  s.occlusion = albedo.a;
  s.metallic = mr.r;
  s.roughness = mr.g;
  s.emissive = texelFetch(u_gbuffer_emissive, pixel, 0).rgb;
  return true;
}
#endif
