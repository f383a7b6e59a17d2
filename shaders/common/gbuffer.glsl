// The G-buffer of the deferred techniques, written by the geometry pass and read
// back into a Surface by lighting passes. C++ side: GBuffer in
// src/render/lighting/gbuffer.hpp (formats, bytes per pixel). Needs frame.glsl.
// The layout is picked by define: THIN_GBUFFER (the light pre-pass's, set by
// GBuffer::defines()), else COMPACT_GBUFFER (--gbuffer compact), else full.
// With MSAA every target is multisampled: read_gbuffer() reads the sample the
// pass runs at (common/msaa.glsl), gbuffer_samples_differ() finds the edges.
#include "common/msaa.glsl"

// World-space direction from the camera through the centre of `pixel`, through
// the far plane's point: the near plane's lies too close to the camera for its
// difference with the camera's position to keep float precision.
vec3 view_ray(ivec2 pixel) {
  vec2 ndc = (vec2(pixel) + 0.5) / u_viewport_size * 2.0 - 1.0;
  vec4 far_point = u_inverse_view_projection * vec4(ndc, kDepthFar, 1.0);
  return normalize(far_point.xyz / far_point.w - u_camera_position.xyz);
}

#if defined(THIN_GBUFFER)
// Thin layout (mode light-prepass: what its light pass needs, 16 B/px with depth):
//   0 normal, roughness  RGBA16  xyz world-space shading normal * 0.5 + 0.5, w roughness
//   1 distance           R32F    distance from the camera (0 = no geometry), as in
//                                the compact layout's fourth word and for the same reasons.
// Albedo, metallic, occlusion and emission are not stored: the light pre-pass's
// second geometry pass reads them from the materials.
#elif !defined(COMPACT_GBUFFER)
// Full layout (--gbuffer full, the reference's five targets, 44 B/px with depth):
//   0 position           RGBA32F      xyz world position, w = 1 where geometry was drawn
//   1 albedo, occlusion  SRGB8_ALPHA8 rgb base colour, a ambient occlusion
//   2 normal             RGBA16       xyz world-space shading normal * 0.5 + 0.5 (16-bit
//                                     unorm: 3e-5 steps; half floats' 1e-3 near 1 moved
//                                     sharp GGX highlights visibly)
//   3 metal-rough        RGBA8        r metallic, g roughness, b 1 for unlit surfaces
//   4 emissive           RGBA16F      rgb emitted radiance
#else
// Compact layout (--gbuffer compact, two targets, 24 B/px with depth):
//   0 albedo, occlusion  SRGB8_ALPHA8 as above
//   1 packed             RGBA32UI     x octahedral normal, 2 x 16-bit unorm
//                                     y emissive r, g as half floats
//                                     z emissive b (half, low 16 bits), metallic and
//                                       roughness (8-bit unorm each, high 16 bits)
//                                     w distance from the camera, 32-bit float; 0 = no
//                                       geometry; negative for unlit surfaces.
//                                       Position = camera + view ray * |distance|.
// The distance sits in the spare fourth word instead of being read from the depth
// buffer: light-volumes writes stencil into that buffer while lighting, and
// sampling a texture that is being written is a feedback loop. It also keeps 32
// bits of precision where DEPTH24 would lose it with a far plane 1000x the near.

vec2 sign_not_zero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

// Unit vector to the octahedron unfolded onto [-1, 1]^2.
vec2 octahedral_encode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
}

vec3 octahedral_decode(vec2 p) {
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
  return normalize(n);
}
#endif

#ifdef GBUFFER_WRITE
#if defined(THIN_GBUFFER)
layout(location = 0) out vec4 out_normal_roughness;
layout(location = 1) out float out_distance;

void write_gbuffer(Surface s) {
  out_normal_roughness = vec4(s.normal * 0.5 + 0.5, s.roughness);
  out_distance = max(length(s.position - u_camera_position.xyz), 1e-30);
}
#elif !defined(COMPACT_GBUFFER)
layout(location = 0) out vec4 out_position;
layout(location = 1) out vec4 out_albedo;
layout(location = 2) out vec4 out_normal;
layout(location = 3) out vec4 out_metallic_roughness;
layout(location = 4) out vec4 out_emissive;

void write_gbuffer(Surface s) {
  out_position = vec4(s.position, 1.0);
  out_albedo = vec4(s.albedo, s.occlusion);
  out_normal = vec4(s.normal * 0.5 + 0.5, 0.0);
  out_metallic_roughness = vec4(s.metallic, s.roughness, s.unlit ? 1.0 : 0.0, 0.0);
  out_emissive = vec4(s.emissive, 0.0);
}
#else
layout(location = 0) out vec4 out_albedo;
layout(location = 1) out uvec4 out_words;

void write_gbuffer(Surface s) {
  out_albedo = vec4(s.albedo, s.occlusion);
  out_words.x = packUnorm2x16(octahedral_encode(s.normal) * 0.5 + 0.5);
  out_words.y = packHalf2x16(s.emissive.rg);
  out_words.z = (packHalf2x16(vec2(s.emissive.b, 0.0)) & 0xffffu) |
                 (packUnorm4x8(vec4(0.0, 0.0, s.metallic, s.roughness)) & 0xffff0000u);
  float distance = max(length(s.position - u_camera_position.xyz), 1e-30);
  out_words.w = floatBitsToUint(s.unlit ? -distance : distance);
}
#endif
#else
#if defined(THIN_GBUFFER)
layout(binding = 0) uniform target2D u_gbuffer_normal_roughness;
layout(binding = 1) uniform target2D u_gbuffer_distance;

// Fills what the thin layout stores; the material's colours read as black.
bool read_gbuffer_sample(ivec2 pixel, int i, out Surface s) {
  float distance = fetch_sample(u_gbuffer_distance, pixel, i).r;
  if (distance == 0.0) return false;
  vec4 normal_roughness = fetch_sample(u_gbuffer_normal_roughness, pixel, i);
  s.position = u_camera_position.xyz + view_ray(pixel) * distance;
  s.normal = normal_roughness.xyz * 2.0 - 1.0;
  s.roughness = normal_roughness.w;
  s.albedo = vec3(0.0);
  s.alpha = 1.0;
  s.occlusion = 1.0;
  s.metallic = 0.0;
  s.emissive = vec3(0.0);
  s.unlit = false;
  return true;
}
#elif !defined(COMPACT_GBUFFER)
layout(binding = 0) uniform target2D u_gbuffer_position;
layout(binding = 1) uniform target2D u_gbuffer_albedo;
layout(binding = 2) uniform target2D u_gbuffer_normal;
layout(binding = 3) uniform target2D u_gbuffer_metallic_roughness;
layout(binding = 4) uniform target2D u_gbuffer_emissive;

// False where no geometry covers the pixel (the background shows).
bool read_gbuffer_sample(ivec2 pixel, int i, out Surface s) {
  vec4 position = fetch_sample(u_gbuffer_position, pixel, i);
  if (position.w == 0.0) return false;
  vec4 albedo = fetch_sample(u_gbuffer_albedo, pixel, i);
  vec4 mr = fetch_sample(u_gbuffer_metallic_roughness, pixel, i);
  s.position = position.xyz;
  s.normal = fetch_sample(u_gbuffer_normal, pixel, i).xyz * 2.0 - 1.0;
  s.albedo = albedo.rgb;
  s.alpha = 1.0;
  s.occlusion = albedo.a;
  s.metallic = mr.r;
  s.roughness = mr.g;
  s.unlit = mr.b > 0.5;
  s.emissive = fetch_sample(u_gbuffer_emissive, pixel, i).rgb;
  return true;
}
#else
layout(binding = 0) uniform target2D u_gbuffer_compact_albedo;
layout(binding = 1) uniform utarget2D u_gbuffer_packed;

bool read_gbuffer_sample(ivec2 pixel, int i, out Surface s) {
  uvec4 words = fetch_sample(u_gbuffer_packed, pixel, i);
  if (words.w == 0u) return false;
  vec4 albedo = fetch_sample(u_gbuffer_compact_albedo, pixel, i);
  vec4 mr = unpackUnorm4x8(words.z);
  float distance = uintBitsToFloat(words.w);
  s.position = u_camera_position.xyz + view_ray(pixel) * abs(distance);
  s.unlit = distance < 0.0;
  s.normal = octahedral_decode(unpackUnorm2x16(words.x) * 2.0 - 1.0);
  s.albedo = albedo.rgb;
  s.alpha = 1.0;
  s.occlusion = albedo.a;
  s.metallic = mr.z;
  s.roughness = mr.w;
  s.emissive = vec3(unpackHalf2x16(words.y), unpackHalf2x16(words.z).x);
  return true;
}
#endif
bool read_gbuffer(ivec2 pixel, out Surface s) { return read_gbuffer_sample(pixel, kThisSample, s); }

// Whether shading sample 0 for the whole pixel would differ from shading each
// sample: some samples hold other surfaces (a silhouette, a crease, a material
// boundary) or none. Samples of one triangle are identical (the geometry pass
// runs once per pixel), so only pixels a triangle edge crosses are tested.
bool gbuffer_samples_differ(ivec2 pixel) {
  Surface first;
  bool covered = read_gbuffer_sample(pixel, 0, first);
  for (int i = 1; i < kSamples; ++i) {
    Surface other;
    if (read_gbuffer_sample(pixel, i, other) != covered) return true;
    if (!covered) continue;
    float range = length(first.position - u_camera_position.xyz);
    if (distance(first.position, other.position) > 1e-3 * range || dot(first.normal, other.normal) < 0.9995 ||
        any(greaterThan(abs(first.albedo - other.albedo), vec3(0.5 / 255.0))) ||
        any(greaterThan(abs(first.emissive - other.emissive), vec3(1e-3) * max(first.emissive, 1.0))) ||
        abs(first.metallic - other.metallic) > 0.5 / 255.0 || abs(first.roughness - other.roughness) > 0.5 / 255.0 ||
        abs(first.occlusion - other.occlusion) > 0.5 / 255.0 || first.unlit != other.unlit) {
      return true;
    }
  }
  return false;
}
#endif
