// A material's parameters as the frame's material table holds them, and the
// bits of Material.flags. C++ twins: MaterialData and the kMaterial* constants
// in src/render/frame/draw_list.hpp (compared by a test).
const uint kMaterialHasNormalTexture = 1u << 0;
const uint kMaterialNormalXyOnly = 1u << 1;     // a two-channel (BC5) normal map: z is rebuilt
const uint kMaterialNormalGreenDown = 1u << 2;  // DirectX's convention: green points down
const uint kMaterialDoubleSided = 1u << 3;
const uint kMaterialUnlit = 1u << 4;            // KHR_materials_unlit
const uint kMaterialAlphaMasked = 1u << 5;

struct Material {
  vec4 base_color_factor;
  vec4 emissive;              // rgb: emissive factor times strength; a: normal scale
  float metallic_factor;
  float roughness_factor;
  float occlusion_strength;   // 0 without an occlusion texture
  float alpha_cutoff;         // < 0 when the material is not alpha-masked
  uint flags;
  uint uv_sets;               // bit s: texture slot s reads UV set 1
  uint padding0;
  uint padding1;
  vec4 uv_transform[10];      // per slot, the two rows of its KHR_texture_transform
};
