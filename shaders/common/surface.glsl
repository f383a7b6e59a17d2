// What shading needs to know about a visible point: filled from material
// textures (material.glsl) or read back from a G-buffer (gbuffer.glsl).
struct Surface {
  vec3 position;
  vec3 normal;
  vec3 albedo;
  float alpha;
  float metallic;
  float roughness;
  float occlusion;
  vec3 emissive;
  bool unlit;  // KHR_materials_unlit: lights add nothing; the colour is in emissive
};
