// Light evaluation shared by every technique: what one light (point, spot or
// directional) adds to a surface seen from the camera, and the terms that do
// not depend on lights.
#include "surface.glsl"
#include "attenuation.glsl"
#include "brdf.glsl"
#include "lights.glsl"
#include "shadows.glsl"

// Radiance that reaches `s` from `light` (colour times falloff, times what its
// shadow maps let through when `shadowed`) and the direction towards it, for
// every light kind. Callers pass `shadowed` as a constant where they can (the
// loops below), so that unshadowed lights compile without the lookup.
vec3 incoming_light(Surface s, Light light, out vec3 l, bool shadowed) {
  uint kind = uint(light.color_kind.w);
  if (kind == kLightDirectional) {
    l = -light.direction.xyz;
    return light.color_kind.rgb * (shadowed ? shadow_visibility(light, s.position, s.normal, l) : 1.0);
  }
  vec3 to_light = light.position_radius.xyz - s.position;
  float distance = length(to_light);
  l = to_light / max(distance, 1e-6);
  float attenuation = light_attenuation(distance, light.position_radius.w);
  if (kind == kLightSpot) {
    float cone = clamp(dot(light.direction.xyz, -l) * light.spot.x + light.spot.y, 0.0, 1.0);
    attenuation *= cone * cone;
  }
  if (shadowed && attenuation > 0.0) attenuation *= shadow_visibility(light, s.position, s.normal, l);
  return light.color_kind.rgb * attenuation;
}

// The pixel being shaded: the fragment's, or in a compute lighting pass
// (COMPUTE_STAGE, common/lighting_targets.glsl) the one its entry point set.
#ifdef COMPUTE_STAGE
ivec2 g_shaded_pixel;
ivec2 shaded_pixel() { return g_shaded_pixel; }
#else
ivec2 shaded_pixel() { return ivec2(gl_FragCoord.xy); }
#endif

// The heatmap debug view compiles every lighting shader with COUNT_LIGHTS:
// each evaluation of a light for a fragment adds one to the fragment's pixel.
#ifdef COUNT_LIGHTS
layout(r32ui, binding = 0) uniform coherent uimage2D u_light_counts;
void count_light_evaluation() { imageAtomicAdd(u_light_counts, shaded_pixel(), 1u); }
#else
void count_light_evaluation() {}
#endif

// What lights add to a surface. With SPLIT_LIGHTING (--split-lighting, the
// diffuse-light and specular-light views) the diffuse and specular sums stay
// apart, for the deferred lighting passes to write each to its own target.
struct LightSum {
#ifdef SPLIT_LIGHTING
  vec3 diffuse;
  vec3 specular;
#else
  vec3 total;
#endif
};

LightSum no_light() {
#ifdef SPLIT_LIGHTING
  return LightSum(vec3(0.0), vec3(0.0));
#else
  return LightSum(vec3(0.0));
#endif
}

// A sum of the diffuse and the specular light that were summed apart elsewhere
// (the light pre-pass's light buffer).
LightSum light_sum(vec3 diffuse, vec3 specular) {
#ifdef SPLIT_LIGHTING
  return LightSum(diffuse, specular);
#else
  return LightSum(diffuse + specular);
#endif
}

vec3 light_total(LightSum sum) {
#ifdef SPLIT_LIGHTING
  return sum.diffuse + sum.specular;
#else
  return sum.total;
#endif
}

// Adds what `light` reflects from `s` towards the camera (direction v) to
// `sum`, looking its shadow maps up when `shadowed`.
void add_light_as(inout LightSum sum, Surface s, vec3 v, Light light, bool shadowed) {
  count_light_evaluation();
  if (s.unlit) return;
  vec3 l;
  vec3 radiance = incoming_light(s, light, l, shadowed);
  if (all(lessThanEqual(radiance, vec3(0.0)))) return;
#ifdef SPLIT_LIGHTING
  vec3 diffuse, specular;
  surface_response_split(s.normal, v, l, s.albedo, s.metallic, s.roughness, diffuse, specular);
  sum.diffuse += diffuse * radiance;
  sum.specular += specular * radiance;
#else
  sum.total += surface_response(s.normal, v, l, s.albedo, s.metallic, s.roughness) * radiance;
#endif
}

// The same, asking the light whether it has maps (a branch every light pays
// for: for the few directional lights of a full-screen pass).
void add_light(inout LightSum sum, Surface s, vec3 v, Light light) { add_light_as(sum, s, v, light, has_shadow_maps(light)); }

// Volume passes draw the shadowed lights with programs built with
// SHADOWED_LIGHTS and the rest with programs built without (VolumePrograms).
#ifdef SHADOWED_LIGHTS
const bool kShadowedLights = true;
#else
const bool kShadowedLights = false;
#endif

// Loops over lights take the shadowed ones first, each with its map lookup,
// and then the rest without: the ShadowAtlas moves the shadowed lights to the
// front of the light buffer, and the tile and cluster lists keep them first
// (common/list_shading.glsl). One loop with the lookup behind a branch would
// cost every light: GPU lanes diverge, and llvmpipe runs both sides of a
// branch for its group of pixels.

// Adds the lights [first, end) of the buffer to `sum`; with `radius_cull`
// those that cannot reach `s` are skipped unevaluated (the same sum: a light
// adds nothing beyond its radius).
void add_light_range(inout LightSum sum, Surface s, vec3 v, uint first, uint end, bool radius_cull) {
  uint i = first;
  for (; i < end && has_shadow_maps(light_at(i)); ++i) {
    if (radius_cull && !light_reaches(light_at(i), s.position)) continue;
    add_light_as(sum, s, v, light_at(i), true);
  }
  for (; i < end; ++i) {
    if (radius_cull && !light_reaches(light_at(i), s.position)) continue;
    add_light_as(sum, s, v, light_at(i), false);
  }
}

// Every light in the buffer.
void add_buffer_lights_culled(inout LightSum sum, Surface s, vec3 v, bool radius_cull) {
  add_light_range(sum, s, v, 0u, u_light_count, radius_cull);
}

// Every light in the buffer; LIGHT_RADIUS_CULL (mode deferred-radius) skips
// those that cannot reach `s`.
#ifdef LIGHT_RADIUS_CULL
const bool kLightRadiusCull = true;
#else
const bool kLightRadiusCull = false;
#endif
void add_buffer_lights(inout LightSum sum, Surface s, vec3 v) { add_buffer_lights_culled(sum, s, v, kLightRadiusCull); }

vec3 shade_unlit_terms(Surface s, vec3 ambient) {
  return ambient * s.albedo * s.occlusion + s.emissive;
}

// Everything that lights `s`: the unlit terms plus every light in the buffer.
vec3 shade_all_lights(Surface s) {
  vec3 v = normalize(u_camera_position.xyz - s.position);
  LightSum sum = no_light();
  add_buffer_lights(sum, s, v);
  return shade_unlit_terms(s, u_ambient.rgb) + light_total(sum);
}
