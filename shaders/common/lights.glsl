// The scene's lights, mirrored from light entities each frame by the
// LightBuffer system. C++ twin: GpuLight in src/render/light_buffer.hpp.
const uint kLightPoint = 0u;
const uint kLightSpot = 1u;
const uint kLightDirectional = 2u;

struct Light {
  vec4 position_radius;  // xyz world position, w radius (m); directional: 0
  vec4 color_kind;       // rgb = colour * intensity, w = kind
  vec4 direction;        // xyz: where a spot or directional light points
  vec4 spot;             // x = 1 / (cos inner - cos outer), y = -cos outer * x,
                         // z = 1 + first shadow view (0: unshadowed), w = shadow view count
  // A point light that moves on the GPU holds its motion in direction (origin,
  // circle radius) and spot.xy (phase, angular speed): render::with_motion.
};

#ifdef NO_STORAGE_BUFFERS
// The compute-free tier (no storage buffers): the same records in a texture,
// four RGBA32F texels per light, kLightTextureWidth texels a row (C++ twins in
// src/render/storage_free.hpp).
const uint kLightTextureWidth = 2048u;
layout(binding = 10) uniform highp sampler2D u_light_texture;

Light light_at(uint i) {
  ivec2 at = ivec2((i * 4u) % kLightTextureWidth, (i * 4u) / kLightTextureWidth);
  return Light(texelFetch(u_light_texture, at, 0), texelFetch(u_light_texture, at + ivec2(1, 0), 0),
               texelFetch(u_light_texture, at + ivec2(2, 0), 0), texelFetch(u_light_texture, at + ivec2(3, 0), 0));
}
#else
#ifdef MOVES_LIGHTS
// The light animation's pass (light_animation/move_lights.comp) places the
// lights that move on the GPU; every other shader only reads them.
layout(std430, binding = 0) buffer LightBlock {
#else
layout(std430, binding = 0) readonly buffer LightBlock {
#endif
  Light u_lights[];
};

Light light_at(uint i) { return u_lights[i]; }
#endif

// Whether a light can contribute at `position`: directional lights always,
// point and spot lights within their radius (beyond it the falloff is zero).
bool light_reaches(Light light, vec3 position) {
  if (uint(light.color_kind.w) == kLightDirectional) return true;
  vec3 d = light.position_radius.xyz - position;
  return dot(d, d) < light.position_radius.w * light.position_radius.w;
}
