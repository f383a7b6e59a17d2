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
};

layout(std430, binding = 0) readonly buffer LightBlock {
  Light u_lights[];
};

// Whether a light can contribute at `position`: directional lights always,
// point and spot lights within their radius (beyond it the falloff is zero).
bool light_reaches(Light light, vec3 position) {
  if (uint(light.color_kind.w) == kLightDirectional) return true;
  vec3 d = light.position_radius.xyz - position;
  return dot(d, d) < light.position_radius.w * light.position_radius.w;
}
