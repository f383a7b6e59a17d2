#version 450 core
// Light volumes (modes light-volumes*, light-prepass): places the unit sphere
// mesh (LightSphere) around a light, scaled to its radius (the mesh
// circumscribes the true sphere). The light is u_light_index, or the instance
// (from u_first_instance) for instanced drawing. Directional lights have no volume.
#include "common/clip.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"

layout(location = 0) in vec3 a_position;

uniform uint u_light_index;
uniform int u_instanced;
uniform uint u_first_instance;  // instanced: the light of instance 0 (VolumePrograms draws two ranges)
uniform float u_circumscribe;

flat out uint v_light;

void main() {
  v_light = u_instanced != 0 ? u_first_instance + uint(gl_InstanceID) : u_light_index;
  Light light = light_at(v_light);
  if (uint(light.color_kind.w) == kLightDirectional) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing is drawn
    return;
  }
  vec3 world = light.position_radius.xyz + a_position * light.position_radius.w * u_circumscribe;
  gl_Position = clip_position(depth_clamped(u_view_projection * vec4(world, 1.0)));
}
