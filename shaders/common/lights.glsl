// The scene's point lights, mirrored from light entities each frame by the
// LightBuffer system. C++ twin: GpuPointLight in src/systems/light_buffer.hpp.
struct PointLight {
  vec4 position_radius;  // xyz world position, w radius (m)
  vec4 color;            // rgb = colour * intensity, w unused
};

layout(std430, binding = 0) readonly buffer LightBlock {
  PointLight u_lights[];
};
